"""Shared fixtures of the Python module's tests: paths of the repository, a small two-class
exemplar built from numpy arrays, and running the Python examples of docs/python.md."""
import os
import pathlib
import re

import numpy as np
import pytest

import tessera

ROOT = pathlib.Path(os.environ.get("TESSERA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
# Real point patterns (spatstat.data, GPL-2 or later; tests/data/spatstat/README.md).
SHARED_DATA = ROOT / "tests" / "data" / "spatstat"


def run_docs_example(heading, cwd):
    """Runs the first ```python block after `heading` in docs/python.md from `cwd`, as a user
    would paste it; returns the names it defined."""
    text = (ROOT / "docs" / "python.md").read_text()
    block = re.search(re.escape(heading) + r".*?```python\n(.*?)```", text, re.S).group(1)
    before = os.getcwd()
    os.chdir(cwd)
    try:
        scope = {}
        exec(compile(block, "docs/python.md", "exec"), scope)
    finally:
        os.chdir(before)
    return scope


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def two_class():
    """Stones on a jittered lattice, a pebble beside each: 2 classes, 72 disks in 12 x 12."""
    rng = np.random.default_rng(3)
    stones = np.array([(x + 1.0, y + 1.0) for x in range(0, 12, 2) for y in range(0, 12, 2)], float)
    stones += rng.uniform(-0.2, 0.2, stones.shape)
    pebbles = stones + np.array([0.8, 0.3])
    positions = np.vstack([stones, pebbles])
    classes = np.array([0] * len(stones) + [1] * len(pebbles))
    radii = np.where(classes == 0, 0.5, 0.2)
    return tessera.exemplar(positions, classes=classes, class_names=["stone", "pebble"], radii=radii,
                            domain=tessera.Domain.box((0, 0), (12, 12)))
