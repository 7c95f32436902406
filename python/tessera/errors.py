"""Exceptions raised by tessera.

Every error the library reports is a :class:`TesseraError` carrying the library's
one-line message, which names the file, line or parameter at fault. The subclasses
also derive from the built-in exception a Python user would catch for that kind of
problem, so ``except ValueError`` catches a bad argument.
"""


class TesseraError(Exception):
    """Base class of tessera's errors."""


class InputError(TesseraError, ValueError):
    """Invalid exemplar or data-file content (a malformed row, a negative radius, ...)."""


class OptionError(TesseraError, ValueError):
    """An invalid option or argument; the message names it."""


class DomainError(TesseraError, ValueError):
    """An output domain that is empty, of the wrong dimension or too small."""


class FileError(TesseraError, OSError):
    """A file that could not be read or written."""


class InternalError(TesseraError, RuntimeError):
    """A broken invariant inside tessera: a bug, please report it."""


class Cancelled(TesseraError):
    """The progress callback returned False: the run stopped and produced nothing."""
