"""The module's surface: every public function documented, keyword options named and
defaulted like the CLI's flags."""
import inspect
import os
import re
import subprocess

import pytest

import tessera
from tessera import _tessera


def test_every_public_name_has_a_docstring():
    for name in tessera.__all__:
        doc = getattr(tessera, name).__doc__
        assert doc and len(doc.strip()) > 20, name
    for name in ("analyze", "save_model", "load_model", "plot_model", "compare_model"):
        assert getattr(tessera, name).__doc__


def test_help_of_synthesize_explains_its_arguments():
    text = inspect.getdoc(tessera.synthesize)
    for word in ("exemplar", "domain", "method", "seed", "iterations", "progress", "Cancelled", "GIL"):
        assert word in text, word


def python_defaults():
    return {name: p.default for name, p in inspect.signature(tessera.synthesize).parameters.items()
            if p.default is not inspect.Parameter.empty}


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
def test_keyword_names_and_defaults_match_the_cli_flags():
    text = subprocess.run([os.environ["TESSERA_CLI"], "synth", "--help"], capture_output=True, text=True,
                          check=True).stdout
    defaults = python_defaults()
    # Flags about the CLI's own files have no keyword of synthesize (gltf_instancing is save's).
    cli_only = {"output", "preview", "meshes", "input_domain", "quiet", "help", "gltf_instancing"}
    found = 0
    for flag, value in re.findall(r"--([a-z0-9-]+)(?: [A-Z]+)?(?:=(\S+))?", text):
        name = flag.replace("-", "_")
        name = "lambda_" if name == "lambda" else name
        if name in cli_only:
            continue
        assert name in defaults or name == "domain", "no keyword for --" + flag
        if value and name != "iterations":
            expected = defaults[name]
            parsed = type(expected)(value) if not isinstance(expected, bool) else value == "true"
            assert parsed == expected, "--%s=%s but %s=%r" % (flag, value, name, expected)
            found += 1
    assert found >= 20
