"""magfem.optimize: ``magfem optimize`` in-process (NLopt's COBYLA over case parameters with
the analytic model; the compiled part is _core.optimize)."""
import json

import numpy as np

from . import _core
from .studies import _argument_error, _axis_text, _count


class OptimizeResult:
    """What ``magfem optimize`` finds (returned by magfem.optimize).

    ``optimum``: {parameter: value} in the parameters' own units; ``objective`` (the
    analytic objective there, N m) and its ``objective_name`` (the study column, e.g.
    ``"peak_torque_Nm"``); ``fe_objective`` (the FE check's value with ``verify_fe``, else
    None); ``evaluations``, ``stop`` (NLopt's reason), ``method`` (of the analytic sweeps);
    ``history``: a dict of numpy columns, one row per evaluation in the order the optimizer
    asked (``evaluation``, the varied parameters, the objective), history.csv's columns;
    ``summary``: summary.json as the command line writes it, but the provenance;
    ``write(dir)`` writes the command line's outputs (summary.json with the provenance,
    history.csv), all or nothing."""

    def __init__(self, run):
        self._run = run
        self.summary = json.loads(run.summary_json())
        self.optimum = {v["name"]: v["value"] for v in self.summary["optimum"]}
        self.objective = self.summary["analytic_value"]
        self.objective_name = self.summary["objective"]
        self.fe_objective = self.summary.get("fe_value")
        self.evaluations = self.summary["evaluations"]
        self.stop = self.summary["stop"]
        self.method = self.summary["method"]
        self.history = run.history()

    def history_csv(self):
        """history.csv's text, as the command line writes it (ten significant digits)."""
        return self._run.history_csv()

    def write(self, out_dir):
        """Writes summary.json and history.csv into out_dir as ``magfem optimize --out
        out_dir`` does (all or nothing); returns the file names."""
        return self._run.write(str(out_dir))

    def __repr__(self):
        return "<magfem.OptimizeResult %s: %s, %s = %.6g after %d evaluations>" % (
            self.method, ", ".join("%s = %.6g" % kv for kv in self.optimum.items()),
            self.objective_name, self.objective, self.evaluations)


def optimize(case, vary, maximize=None, minimize=None, rotate=None, axis=None, angles=None,
             constraints=(), xtol=1e-4, verify_fe=False, progress=None, *, order=None,
             mesh_scale=1.0):
    """Runs ``magfem optimize`` on a Case in-process; returns an OptimizeResult.

    ``vary``: {parameter: (lower, upper)} in the parameters' own units (--vary NAME=LO:HI);
    one of ``maximize`` / ``minimize``: the objective as the command line names it
    (``"peak_torque"``, ``"torque_at:DEG"``); ``rotate``, ``axis``, ``angles`` (degrees): the
    sweep whose torque the objective takes, as in ``magfem.study``; ``constraints``:
    inequalities between expressions of the varied parameters, a string or a list
    (``"R_out - R_in <= 15"``); ``xtol``: NLopt's relative tolerance on the variables;
    ``verify_fe``: one FE sweep at the optimum (with ``order`` and ``mesh_scale``) beside the
    analytic value. The optimizer (NLopt LN_COBYLA) always evaluates the analytic model.

    ``progress``: None, True (a line per evaluation) or ``progress(done, limit)`` per
    evaluation (the limit of 500 evaluations stands for the unknown total). The GIL is
    released meanwhile; Ctrl-C stops before the next evaluation and raises KeyboardInterrupt.
    Raises InputError for bad arguments (the field is the argument's name) and SolveError when
    the model fails inside the bounds or no point satisfies the constraints.
    """
    if (maximize is None) == (minimize is None):
        raise _argument_error("maximize", "give one of maximize= or minimize=", "<optimize>")
    if not isinstance(vary, dict) or not vary:
        raise _argument_error("vary", "a dict {parameter: (lower, upper)}, not %r" % (vary,),
                              "<optimize>")
    request = _core.OptimizeRequest()
    bounds = []
    for name, pair in vary.items():
        b = np.asarray(pair, dtype=float).ravel()
        if b.size != 2:
            raise _argument_error("vary", "(lower, upper) for %r, not %r" % (name, pair),
                                  "<optimize>")
        bounds.append((str(name), float(b[0]), float(b[1])))
    request.vary = bounds
    request.maximize = maximize is not None
    request.objective = str(maximize if maximize is not None else minimize)
    request.rotate = "" if rotate is None else str(rotate)
    request.axis = _axis_text(axis)
    if angles is not None:
        request.angles = [float(v) for v in np.asarray(angles, dtype=float).ravel()]
    request.constraints = [constraints] if isinstance(constraints, str) else list(constraints)
    request.xtol = float(xtol)
    request.verify_fe = bool(verify_fe)
    request.order = _count("order", order)
    request.mesh_scale = float(mesh_scale)
    run = _core.optimize(case._path or "", case._text or "", case._name or "", case._params,
                         request, progress)
    return OptimizeResult(run)
