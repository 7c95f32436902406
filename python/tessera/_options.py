"""The keyword options of tessera.synthesize (det, pcf, dynamic), tessera.Grower,
tessera.pair_correlation and tessera.metrics, made from the library's option tables
(``_tessera.option_tables()``, include/tessera/option_table.hpp): one table per method
declares each option once (name, kind, default, doc, check), and the CLI's flags, these
keywords, their defaults, their docs and their checks all come from it.
"""

import inspect

from . import _tessera
from .errors import OptionError

TABLES = _tessera.option_tables()


def keywords(method):
    """The keywords of one method's options, in table order."""
    return [row["keyword"] for row in TABLES[method]]


def defaults(method):
    return {row["keyword"]: row["default"] for row in TABLES[method]}


def merged(methods):
    """Each keyword over `methods` once: (keyword, default, [(method, row)]); the default is
    None where the methods' defaults differ (each method then uses its own)."""
    rows = {}
    for method in methods:
        for row in TABLES[method]:
            rows.setdefault(row["keyword"], []).append((method, row))
    out = []
    for keyword, owners in rows.items():
        values = {repr(row["default"]) for _, row in owners}
        out.append((keyword, owners[0][1]["default"] if len(values) == 1 else None, owners))
    return out


def parameters(methods):
    """Keyword-only inspect.Parameters for the options of `methods`."""
    return [inspect.Parameter(keyword, inspect.Parameter.KEYWORD_ONLY, default=default)
            for keyword, default, _ in merged(methods)]


def doc(methods):
    """The options' section of a docstring: each keyword with its default, its doc and what
    it accepts; the method named where only some methods have it or their docs differ."""
    lines = []
    for keyword, default, owners in merged(methods):
        lines.append("  %s=%r" % (keyword, default))
        same_doc = len({row["doc"] for _, row in owners}) == 1
        named = len(methods) > 1 and (len(owners) < len(methods) or not same_doc)
        for method, row in owners[:1] if same_doc else owners:
            accepts = "" if row["kind"] in ("text", "flag") else " Accepts %s." % row["accepts"]
            if default is None and row["default"] is not None:
                accepts += " Default %r." % (row["default"],)
            lines.append("      %s%s%s" % (method + ": " if named else "", row["doc"], accepts))
    return "\n".join(lines)


def with_signature(function, head, methods, tail=()):
    """Gives `function` (which takes the options as **kwargs) the signature head + the
    options of `methods` + tail, and its docstring the options' section."""
    signature = inspect.signature(function)
    named = [signature.parameters[name] for name in head]
    rest = [signature.parameters[name] for name in tail]
    function.__signature__ = signature.replace(parameters=named + parameters(methods) + rest)
    function.__doc__ = (function.__doc__ or "").rstrip() + "\n\n    Options (from the library's option table):\n" + \
        "\n".join("    " + line for line in doc(methods).splitlines()) + "\n"
    return function


def check_keywords(name, given, methods):
    """A TypeError, as Python raises for any function, for a keyword no method has."""
    known = {keyword for method in methods for keyword in keywords(method)}
    for keyword in given:
        if keyword not in known:
            raise TypeError("%s() got an unexpected keyword argument %r" % (name, keyword))


def alternatives(names):
    """'a' or 'b'; 'a', 'b' or 'c'."""
    quoted = ["%r" % (name,) for name in names]
    return quoted[0] if len(quoted) == 1 else "%s or %s" % (", ".join(quoted[:-1]), quoted[-1])


def of_method(name, method, methods, options):
    """The keywords of `options` that belong to `method`, one of the `methods` of the call
    `name`: a TypeError for a keyword none has, an OptionError for another method or for an
    option only other methods have set off their defaults (a value that is some owner's
    default is taken for an unset option, as None is)."""
    check_keywords(name, options, methods)
    if method not in methods:
        raise OptionError("method must be %s, got %r" % (alternatives(methods), method))
    mine = set(keywords(method))
    for keyword, value in options.items():
        if keyword in mine or value is None:
            continue
        owners = [m for m in methods if m != method and keyword in keywords(m)]
        if all(value != defaults(m)[keyword] for m in owners):
            raise OptionError("%s applies to method=%s only" % (keyword, alternatives(owners)))
    return {keyword: value for keyword, value in options.items() if keyword in mine}
