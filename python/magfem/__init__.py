"""magfem: finite-element magnetostatics from Python (issue 32, first slice).

So far: ``__version__``, and the exception types the case and solve calls will raise.
"""
from ._core import __version__


class InputError(ValueError):
    """A case the reader rejects. ``file``, ``line`` (1-based, or None) and ``field`` (the
    YAML path such as ``regions[2].material``, or None) say where."""

    def __init__(self, message, file=None, line=None, field=None):
        super().__init__(message)
        self.file = file
        self.line = line
        self.field = field


class SolveError(RuntimeError):
    """A solve that did not produce a result (no convergence, a failed mesh)."""


__all__ = ["__version__", "InputError", "SolveError"]
