"""magfem: finite-element magnetostatics from Python (issue 32, first slice).

So far: ``__version__``, ``Case`` (load, from_dict, with_params, to_yaml: the case read and
validated by the same reader as ``magfem solve``) and the exception types.
"""
from . import _core
from ._core import __version__

# The compiled reader raises this (a ValueError carrying file, line, field).
InputError = _core._InputError
InputError.__doc__ = """A case the reader rejects. ``file`` (``<dict>`` for Case.from_dict),
``line`` (1-based, or None) and ``field`` (the YAML path, or None) say where."""


class SolveError(RuntimeError):
    """A solve that did not produce a result (no convergence, a failed mesh)."""


class Case:
    """A validated case: a case file or a dict in the case-file schema, with parameter
    overrides (the ``parameters:`` section, as ``magfem solve --param name=value``)."""

    def __init__(self, path=None, text=None, name=None, params=None):
        self._path, self._text, self._name = path, text, name
        self._params = dict(params or {})
        if path is not None:
            resolved = _core.check_case_file(path, self._params)
        else:
            resolved = _core.check_case_text(text, name, self._params)
        self.parameters = dict(resolved)
        """Resolved parameter values (overrides applied), in the case's units."""

    @classmethod
    def load(cls, path, params=None):
        """Reads a case file; ``params`` maps parameter names to values. Raises InputError."""
        return cls(path=str(path), params=params)

    @classmethod
    def from_dict(cls, case, params=None):
        """A case from a dict in the case-file schema, dumped to YAML and read by the same
        reader, so validation and messages are those of a file named ``<dict>``."""
        import yaml  # python3-yaml
        return cls(text=yaml.safe_dump(case, sort_keys=False), name="<dict>", params=params)

    def with_params(self, **overrides):
        """A copy with more parameter overrides, e.g. ``case.with_params(gap=2.0)``."""
        return Case(self._path, self._text, self._name, {**self._params, **overrides})

    def to_yaml(self):
        """The case's YAML text (the file's text for a loaded case, without overrides)."""
        if self._text is not None:
            return self._text
        with open(self._path, encoding="utf-8") as f:
            return f.read()


__all__ = ["__version__", "Case", "InputError", "SolveError"]
