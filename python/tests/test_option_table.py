"""The option tables (include/tessera/option_table.hpp) are the one declaration of every
option: walk them and check that each option is a keyword of tessera.synthesize or
tessera.Grower with the table's default, a flag of `tessera synth` / `tessera grow` /
`tessera edit` / `tessera analyze` whose --help shows that default, a row of docs/cli.md,
and that a value outside its check is refused with the option named as each front end
spells it (editing has no Python call, and tessera.analyze takes the analysis's keywords
explicitly: their tables are walked for the CLI and the docs)."""

import inspect
import math
import os
import subprocess

import pytest

import tessera
from tessera import _tessera

TABLES = _tessera.option_tables()
COMMAND = {"det": "synth", "pcf": "synth", "grow": "grow", "edit": "edit", "analyze": "analyze"}
PYTHON_METHODS = ("det", "pcf", "grow")


def rows(methods=tuple(COMMAND)):
    return [(method, row) for method in methods for row in TABLES[method]]


def row_id(item):
    return "%s-%s" % (item[0], item[1]["name"])


def signature_of(method):
    return inspect.signature(tessera.Grower if method == "grow" else tessera.synthesize).parameters


def expected_python_default(method, row):
    """The keyword's default: the row's, or None where det and pcf differ (each its own)."""
    if method == "grow":
        return row["default"]
    other = [r for r in TABLES["pcf" if method == "det" else "det"] if r["name"] == row["name"]]
    return None if other and other[0]["default"] != row["default"] else row["default"]


def bad_value(row):
    """A value the row's check refuses, or None when every value of its kind is accepted."""
    if row["kind"] == "choice":
        return "nonsense"
    if row["kind"] not in ("integer", "number"):
        return None
    lo, hi = _bounds(row["accepts"])
    if lo is not None:
        return lo - 1 if row["kind"] == "integer" else lo - 0.5
    if hi is not None:
        return hi + 1
    return None


def _bounds(accepts):
    """(lower, upper) read from describe_accepted's text ('an integer from 1 to 4096', '>= 0')."""
    words = accepts.split()
    lo = hi = None
    for i, word in enumerate(words[:-1]):
        value = words[i + 1]
        if word in (">=", ">", "from"):
            lo = float(value)
        if word in ("<=", "<", "to"):
            hi = float(value)
    return lo, hi


@pytest.mark.parametrize("item", rows(PYTHON_METHODS), ids=row_id)
def test_every_option_is_a_keyword_with_the_tables_default(item):
    method, row = item
    parameters = signature_of(method)
    assert row["keyword"] in parameters, "no keyword %s for %s" % (row["keyword"], method)
    parameter = parameters[row["keyword"]]
    assert parameter.kind is inspect.Parameter.KEYWORD_ONLY
    assert parameter.default == expected_python_default(method, row)
    doc = inspect.getdoc(tessera.Grower.__init__ if method == "grow" else tessera.synthesize)
    assert row["doc"] in doc


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
@pytest.mark.parametrize("item", rows(), ids=row_id)
def test_every_option_is_a_flag_showing_its_default(item, help_text):
    method, row = item
    text = help_text(COMMAND[method])
    lines = [line for line in text.splitlines() if line.strip().startswith(row["flag"] + " ")
             or line.strip() == row["flag"]]
    assert lines, "%s not in tessera %s --help" % (row["flag"], COMMAND[method])
    if row["default"] is not None and row["kind"] != "flag" and expected_python_default(method, row) is not None:
        default = lines[0].split()[1].split("=", 1)
        assert len(default) == 2, lines[0]
        value = default[1]
        if isinstance(row["default"], float):
            assert math.isclose(float(value), row["default"]), lines[0]
        else:
            assert value == str(row["default"]), lines[0]


@pytest.mark.parametrize("item", rows(), ids=row_id)
def test_every_option_is_in_the_cli_docs(item, root):
    method, row = item
    docs = (root / "docs" / "cli.md").read_text()
    section = docs[docs.index("## `tessera %s`" % COMMAND[method]):]
    section = section[:section.index("\n## ", 1)] if "\n## " in section[1:] else section
    assert "| `%s" % row["flag"] in section, "%s has no row in docs/cli.md's tessera %s" % (row["flag"], COMMAND[method])


@pytest.mark.parametrize("item", [i for i in rows(PYTHON_METHODS) if bad_value(i[1]) is not None], ids=row_id)
def test_a_value_outside_the_check_names_the_keyword(item, two_class):
    method, row = item
    value = bad_value(row)
    with pytest.raises(tessera.OptionError) as error:
        if method == "grow":
            tessera.Grower(two_class, **{row["keyword"]: value})
        else:
            tessera.synthesize(two_class, method=method, **{"iterations": 0, row["keyword"]: value})
    assert str(error.value).startswith(row["keyword"] + " must be " + row["accepts"]), str(error.value)


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
@pytest.mark.parametrize("item", [i for i in rows() if bad_value(i[1]) is not None], ids=row_id)
def test_a_value_outside_the_check_names_the_flag(item, tmp_path, root):
    method, row = item
    value = bad_value(row)
    if isinstance(value, float) and value == int(value):
        value = int(value)
    inputs = [str(root / "examples" / "two_class_2d.json")]
    target = ["--region", "box:20,20"] if method == "grow" else ["--method", method]
    if method == "edit":
        edit = tmp_path / "edit.json"
        edit.write_text('{"element": 0, "offset": [0.1, 0.0]}')
        inputs.append(str(edit))
        target = []
    if method == "analyze":
        target = []
    result = subprocess.run([os.environ["TESSERA_CLI"], COMMAND[method], *inputs,
                             "-o", str(tmp_path / "out.json"), *target, row["flag"], str(value)],
                            capture_output=True, text=True)
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith("tessera: error: " + row["flag"]), result.stderr
    assert len(result.stderr.splitlines()) == 1
    assert not (tmp_path / "out.json").exists()


def test_an_unknown_keyword_is_a_type_error(two_class):
    with pytest.raises(TypeError, match="unexpected keyword argument 'radious'"):
        tessera.synthesize(two_class, radious=2.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'radious'"):
        tessera.Grower(two_class, radious=2.0)


@pytest.fixture(scope="module")
def help_text():
    cache = {}

    def text(command):
        if command not in cache:
            cache[command] = subprocess.run([os.environ["TESSERA_CLI"], command, "--help"], capture_output=True,
                                            text=True, check=True).stdout
        return cache[command]
    return text
