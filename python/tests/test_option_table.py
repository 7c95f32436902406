"""The option tables (include/tessera/option_table.hpp) are the one declaration of every
option: walk them and check that each option is a keyword of tessera.synthesize (det, pcf,
dynamic),
tessera.Grower, tessera.pair_correlation, tessera.metrics and tessera.decompose with the table's default, a
flag of `tessera synth` / `grow` / `edit` / `analyze` / `metrics` whose --help shows that
default, a row of docs/cli.md, and that a value outside its check is refused with the
option named as each front end spells it (editing has no Python call, and tessera.analyze
takes the analysis's keywords explicitly: their tables are walked for the CLI and the docs)."""

import inspect
import math
import os
import subprocess

import pytest

import tessera
from tessera import _tessera

TABLES = _tessera.option_tables()
# The commands each table makes flags for (the estimate's: analyze --standard-pcf and metrics).
COMMANDS = {"det": ("synth",), "pcf": ("synth",), "dynamic": ("synth",), "grow": ("grow",), "edit": ("edit",), "analyze": ("analyze",),
            "pair_correlation": ("analyze", "metrics"), "brush": ("brush",), "low_pass": ("analyze",)}
PYTHON_METHODS = ("det", "pcf", "dynamic", "grow", "pair_correlation", "brush", "low_pass")
# The methods of tessera.synthesize: one keyword per option name over them.
SYNTH_METHODS = ("det", "pcf", "dynamic")


def rows(methods=tuple(COMMANDS)):
    return [(method, row) for method in methods for row in TABLES[method]]


def flag_rows():
    """(method, command, row) for every flag a command makes from a table."""
    return [(method, command, row) for method, row in rows() for command in COMMANDS[method]]


def row_id(item):
    return "-".join(part if isinstance(part, str) else part["name"] for part in item)


def functions_of(method):
    """The Python calls that take a table's keywords."""
    if method == "grow":
        return [tessera.Grower.__init__]
    if method == "pair_correlation":
        return [tessera.pair_correlation, tessera.metrics]
    if method == "brush":
        return [tessera.BrushCanvas.__init__, tessera.brush]
    if method == "low_pass":
        return [tessera.decompose]
    return [tessera.synthesize]


def expected_python_default(method, row):
    """The keyword's default: the row's, or None where the methods of synthesize that have it
    differ (each then uses its own)."""
    if method not in SYNTH_METHODS:
        return row["default"]
    defaults = {repr(r["default"]) for m in SYNTH_METHODS for r in TABLES[m] if r["name"] == row["name"]}
    return row["default"] if len(defaults) == 1 else None


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
    """(lower, upper) read from describe_accepted's text ('an integer from 1 to 4096', '>= 0',
    'an integer from 2 to 1000000, or 0 (automatic)')."""
    words = accepts.replace(",", " ").split()
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
    for function in functions_of(method):
        parameters = inspect.signature(function).parameters
        assert row["keyword"] in parameters, "no keyword %s for %s" % (row["keyword"], function.__qualname__)
        parameter = parameters[row["keyword"]]
        assert parameter.kind is inspect.Parameter.KEYWORD_ONLY
        assert parameter.default == expected_python_default(method, row)
        assert row["doc"] in inspect.getdoc(function)


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
@pytest.mark.parametrize("item", flag_rows(), ids=row_id)
def test_every_option_is_a_flag_showing_its_default(item, help_text):
    method, command, row = item
    text = help_text(command)
    lines = [line for line in text.splitlines() if line.strip().startswith(row["flag"] + " ")
             or line.strip() == row["flag"]]
    assert lines, "%s not in tessera %s --help" % (row["flag"], command)
    if row["default"] is not None and row["kind"] != "flag" and expected_python_default(method, row) is not None:
        default = lines[0].split()[1].split("=", 1)
        assert len(default) == 2, lines[0]
        value = default[1]
        if isinstance(row["default"], float):
            assert math.isclose(float(value), row["default"]), lines[0]
        else:
            assert value == str(row["default"]), lines[0]


@pytest.mark.parametrize("item", flag_rows(), ids=row_id)
def test_every_option_is_in_the_cli_docs(item, root):
    method, command, row = item
    docs = (root / "docs" / "cli.md").read_text()
    section = docs[docs.index("## `tessera %s`" % command):]
    section = section[:section.index("\n## ", 1)] if "\n## " in section[1:] else section
    assert "| `%s" % row["flag"] in section, "%s has no row in docs/cli.md's tessera %s" % (row["flag"], command)


@pytest.mark.parametrize("item", [i for i in rows(PYTHON_METHODS) if bad_value(i[1]) is not None], ids=row_id)
def test_a_value_outside_the_check_names_the_keyword(item, two_class):
    method, row = item
    value = bad_value(row)
    calls = {"grow": [lambda **kw: tessera.Grower(two_class, **kw)],
             "pair_correlation": [lambda **kw: tessera.pair_correlation(two_class, **kw),
                                  lambda **kw: tessera.metrics(two_class, two_class, **kw)],
             "brush": [lambda **kw: tessera.BrushCanvas(((0, 0), (10, 10)), **kw),
                       lambda **kw: tessera.brush(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                                               "brush", "design_2d.json"), **kw)],
             "low_pass": [lambda **kw: tessera.decompose(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                                                      "dynamic", "swirl_particles_2d.json"), **kw)]}
    default = [lambda **kw: tessera.synthesize(two_class, method=method, **{"iterations": 0, **kw})]
    for call in calls.get(method, default):
        with pytest.raises(tessera.OptionError) as error:
            call(**{row["keyword"]: value})
        assert str(error.value).startswith(row["keyword"] + " must be " + row["accepts"]), str(error.value)


@pytest.mark.skipif("TESSERA_CLI" not in os.environ, reason="TESSERA_CLI is set by CTest")
@pytest.mark.parametrize("item", [i for i in flag_rows() if bad_value(i[2]) is not None], ids=row_id)
def test_a_value_outside_the_check_names_the_flag(item, tmp_path, root):
    method, command, row = item
    value = bad_value(row)
    if isinstance(value, float) and value == int(value):
        value = int(value)
    example = str(root / "examples" / "two_class_2d.json")
    out = tmp_path / "out.json"
    args = [example, "-o", str(out)]
    if method == "grow":
        args += ["--region", "box:20,20"]
    elif method in SYNTH_METHODS:
        args += ["--method", method]
    elif method == "edit":
        edit = tmp_path / "edit.json"
        edit.write_text('{"element": 0, "offset": [0.1, 0.0]}')
        args = [example, str(edit), "-o", str(out)]
    elif method == "pair_correlation" and command == "analyze":
        out = tmp_path / "g.csv"
        args = [example, "--standard-pcf", "--csv", str(out)]
    elif method == "pair_correlation":
        args = [example, example, "-o", str(out)]
    elif method == "brush":
        args = [str(root / "examples" / "brush" / "design_2d.json"), "-o", str(out)]
    elif method == "low_pass":
        args += ["--decompose", "--detail", str(tmp_path / "detail.json")]
    result = subprocess.run([os.environ["TESSERA_CLI"], command, *args, row["flag"], str(value)],
                            capture_output=True, text=True)
    assert result.returncode == 2, result.stderr
    assert result.stderr.startswith("tessera: error: " + row["flag"] + " must be " + row["accepts"]), result.stderr
    assert len(result.stderr.splitlines()) == 1
    assert not out.exists()


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
