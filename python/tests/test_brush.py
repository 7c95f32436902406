"""tessera.BrushCanvas and tessera.brush (include/tessera/brush.hpp, docs/brush.md): painting
from Python gives what the session file gives, element fields follow the strokes, bad input
is a clear error."""

import math
import os

import numpy as np
import pytest

import tessera

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
EXAMPLES = os.path.join(ROOT, "examples")


def painted_canvas(**options):
    c = tessera.BrushCanvas(((0, 0), (30, 20)), seed=2, **options)
    c.add_exemplar("sticks", os.path.join(EXAMPLES, "sticks_2d.json"))
    report = c.paint("sticks", [(3, 10), (27, 10)], width=4)
    assert report["added"] > 10
    return c


def test_painted_elements_are_locked_and_follow_the_stroke():
    c = painted_canvas()
    out = c.arrangement
    assert out.locked.all()
    assert np.all(np.abs(out.centroids[:, 1] - 10) <= 3), "inside the stroke's band"
    d = c.sample_directions
    assert d.shape == (out.sample_count, 2)
    assert np.all(np.abs(d[:, 1]) < 0.02), "painted along +x: o(s) along +x"


def test_fill_completes_the_canvas_and_keeps_painted_elements():
    c = painted_canvas()
    before = len(c)
    painted = c.arrangement.positions.copy()
    report = c.fill()
    assert report["added"] > before
    assert len(c) == before + report["added"]
    assert np.array_equal(c.arrangement.positions[:len(painted)], painted), "painted elements never move"
    assert set(c.energies) == {"distribution", "conflict", "graph", "alignment", "continuity", "rigidity"}


def test_a_session_file_replays_to_the_same_arrangement_as_its_calls():
    session = os.path.join(EXAMPLES, "brush", "design_2d.json")
    a = tessera.brush(session, threads=1)
    b = tessera.brush(session, threads=2)
    assert len(a) == len(b) > 500
    assert np.array_equal(a.sample_directions, b.sample_directions)


def test_bad_input_is_a_clear_error(tmp_path):
    with pytest.raises(tessera.OptionError, match="sigma must be a number > 0"):
        tessera.BrushCanvas(((0, 0), (10, 10)), sigma=0)
    c = painted_canvas()
    with pytest.raises(tessera.OptionError, match="no palette entry named 'leaves'"):
        c.paint("leaves", [(1, 1), (2, 2)])
    with pytest.raises(tessera.InputError, match="at least 2 points"):
        c.direct([(1, 1)])
    bad = tmp_path / "s.json"
    bad.write_text('{"format": "tessera-brush", "canvas": "box:0,0,9,9", "palette": {"d": "%s"}, "ops": [{"op": 3}]}'
                   % os.path.join(EXAMPLES, "poisson_disk_2d.json").replace("\\", "/"))
    with pytest.raises(tessera.InputError, match=r"ops\[0\]\.op"):
        tessera.brush(bad)
