"""magfem: finite-element magnetostatics from Python (issue 32).

So far: ``__version__``, ``Case`` (load, from_dict, with_params, to_yaml: the case read and
validated by the same reader as ``magfem solve``), ``Case.solve`` returning a ``Solution``
(the same in-process pipeline as ``magfem solve``), ``analytic``, ``sweep`` (``magfem sweep``
in-process, numpy columns), ``study``, ``optimize``, ``actuator``, ``coil_pitch``,
``validate`` and the exception types; sweep, study and validate keep the command line's
checkpoint and resume from it (``checkpoint_dir=``, ``resume=True``).
"""
import contextlib
import os
import warnings

from . import _core
from ._core import __version__
from .optimize import OptimizeResult, optimize
from .solution import AnalyticSolution, Mesh, Solution
from .studies import (ActuatorResult, CoilPitchResult, StudyResult, SweepResult,
                      ValidationResult, _whole_number, actuator, coil_pitch, study, sweep,
                      validate)

# The compiled reader raises this (a ValueError carrying file, line, field).
InputError = _core._InputError
InputError.__doc__ = """A case the reader rejects. ``file`` (``<dict>`` for Case.from_dict),
``line`` (1-based, or None) and ``field`` (the YAML path, or None) say where."""


def _argument_error(field, message):
    """An InputError about an argument of a call, as the C++ side words one ("<solve>")."""
    err = InputError("<solve>: %s: %s" % (field, message))
    err.file, err.line, err.field = "<solve>", None, field
    return err


# The pipeline raises this (a RuntimeError) when the solver fails.
SolveError = _core._SolveError
SolveError.__doc__ = """A solve that did not produce a result (no convergence, a singular
system); the message is the command line's "solver failed: ..." text."""


class AdaptWarning(UserWarning):
    """An adaptive solve stopped at max_passes, max_unknowns or the memory guard before its
    accuracy; the solution of the last pass is returned (``sol.adapt["converged"]`` False)."""


@contextlib.contextmanager
def _thread_limit(threads):
    """MAGFEM_THREADS for the duration of a call (core/thread_count.hpp reads it at every
    parallel loop). Process-wide: concurrent solves share the last value set."""
    if threads is None:
        yield
        return
    if isinstance(threads, bool) or not isinstance(threads, int) or threads < 1:
        raise _argument_error("threads", "must be a positive integer, not %r" % (threads,))
    before = os.environ.get("MAGFEM_THREADS")
    os.environ["MAGFEM_THREADS"] = str(threads)
    try:
        yield
    finally:
        if before is None:
            del os.environ["MAGFEM_THREADS"]
        else:
            os.environ["MAGFEM_THREADS"] = before


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

    def solve(self, order=None, mesh_scale=1.0, threads=None, progress=None, accuracy=None,
              max_passes=None, max_unknowns=None):
        """Meshes and solves the case in-process, as ``magfem solve`` does; returns a Solution.

        ``order``: 1 or 2 (None: as in the case, like the command line's --order);
        ``mesh_scale``: multiplies every mesh size (--mesh-scale); ``threads``: magfem's own
        worker threads for this call (MAGFEM_THREADS; None: all cores); ``progress``: None
        (silent), True (the command line's progress lines on stderr) or a callable
        ``progress(kind, text)`` with kind "stage", "note" or "iteration" (an adaptive
        solve's passes come as notes, "pass 1 ...", the command line's lines).

        Adaptive refinement (``magfem solve --accuracy PCT --max-passes N --max-unknowns N``):
        ``accuracy`` (percent, 0 < accuracy < 100) refines pass by pass until the estimated
        energy error and the estimated errors of the case's ``adapt: quantities`` are below
        it; ``max_passes`` and ``max_unknowns`` bound the loop. None keeps the case's
        ``adapt:`` section (a case with one solves adaptively without ``accuracy``); limits
        without any accuracy raise InputError. A limit reached first is not an error: the
        last pass is returned, ``sol.adapt["converged"]`` is False and an AdaptWarning (a
        UserWarning) says why. ``sol.adapt`` holds the passes and estimates.

        The GIL is released while solving. Ctrl-C raises KeyboardInterrupt at the next
        stage or Newton step (meshing, a direct factorization and an AMG-preconditioned
        Krylov solve finish first); an exception raised by ``progress`` ends the solve the
        same way. Raises InputError (bad case or argument, a geometry the mesher rejects)
        and SolveError (no convergence).
        """
        max_passes = _whole_number("max_passes", max_passes, "<solve>")
        with _thread_limit(threads):
            core = _core.solve(self._path or "", self._text or "", self._name or "",
                               self._params, 0 if order is None else order, mesh_scale,
                               progress, accuracy, max_passes, max_unknowns)
        warning = core.adapt_warning()
        if warning:
            warnings.warn(warning, AdaptWarning, stacklevel=2)
        return Solution(core)

    def to_yaml(self):
        """The case's YAML text (the file's text for a loaded case, without overrides)."""
        if self._text is not None:
            return self._text
        with open(self._path, encoding="utf-8") as f:
            return f.read()


def analytic(case, model="charge", tolerance=1e-6, n_max=150):
    """Answers a case with the analytic models, as ``magfem analytic`` does; returns an
    AnalyticSolution (probes, forces, coils, inductance_H, summary, write).

    ``model``: "charge" (surface charges with imaging in permeable spheres; ``tolerance`` is
    its relative quadrature tolerance) or "harmonic" (spherical harmonics up to degree
    ``n_max``); axisymmetric cases use their closed forms. The GIL is released meanwhile.
    Raises InputError for a case the models cannot answer.
    """
    if model not in ("charge", "harmonic"):
        raise _argument_error("model", "must be 'charge' or 'harmonic', not %r" % (model,))
    core = _core.analytic(case._path or "", case._text or "", case._name or "", case._params,
                          model, tolerance, n_max)
    return AnalyticSolution(core)


__all__ = ["__version__", "ActuatorResult", "AdaptWarning", "AnalyticSolution", "Case",
           "CoilPitchResult", "InputError", "Mesh", "OptimizeResult", "Solution", "SolveError",
           "StudyResult", "SweepResult", "ValidationResult", "actuator", "analytic",
           "coil_pitch", "optimize", "study", "sweep", "validate"]
