"""magfem.sweep (and the other studies): the command line's studies in-process, their tables
as numpy columns (the compiled part is _core.sweep)."""
import json

import numpy as np

from . import _core


def _argument_error(field, message):
    """An InputError about an argument of a study call ("<sweep>: field: message")."""
    err = _core._InputError("<sweep>: %s: %s" % (field, message))
    err.file, err.line, err.field = "<sweep>", None, field
    return err


def _count(name, value):
    """None -> 0 (the library's "as many as cores" / "as in the case"), else a positive int."""
    if value is None:
        return 0
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise _argument_error(name, "must be a positive integer, not %r" % (value,))
    return int(value)


class SweepResult(dict):
    """A sweep's table: a dict of numpy columns named as the command line's sweep.csv
    (``angle_deg, Tx, Ty, Tz, Fx, Fy, Fz`` for rotating sweeps, N m and N; ``position_mm,
    Fz_N`` for translate sweeps), successful positions only, in the order given.

    ``summary``: summary.json as ``magfem sweep`` writes it, but the provenance and the peak
    memory; ``method``, ``positions`` (per position: ok, seconds, error, ...) and ``failed``
    (the number of failed positions) are taken from it. ``csv()`` is sweep.csv's text."""

    def __init__(self, columns, summary):
        super().__init__(columns)
        self.summary = summary
        self.method = summary["method"]
        self.positions = summary["positions"]
        self.failed = summary["failed_positions"]

    @property
    def columns(self):
        """The column names, in sweep.csv's order."""
        return list(self.keys())

    def csv(self):
        """sweep.csv as the command line writes it (ten significant digits)."""
        lines = [",".join(self.columns)]
        for row in zip(*self.values()):
            lines.append(",".join("%.10g" % v for v in row))
        return "\n".join(lines) + "\n"

    def __repr__(self):
        return "<magfem.SweepResult %s: %d positions, %d failed>" % (
            self.method, len(self.positions), self.failed)


def _axis_text(axis):
    if axis is None:
        return ""
    if isinstance(axis, str):
        return axis
    a = np.asarray(axis, dtype=float).ravel()
    if a.size != 3:
        raise _argument_error("axis", "x, y, z or three numbers, not %r" % (axis,))
    return ",".join(repr(float(x)) for x in a)


def sweep(case, rotate=None, axis=None, angles=None, analytic=False, jobs=None, progress=None,
          *, translate=None, positions=None, point=None, surface_radius=None, order=None,
          mesh_scale=1.0):
    """Runs ``magfem sweep`` on a Case in-process and returns a SweepResult (numpy columns).

    Rotating sweeps (3D and planar 2D cases): ``rotate`` names the group to turn, ``axis``
    ("x", "y", "z" or three numbers; None: "y" in 3D, "z" for planar cases, which turn about
    z only), ``angles`` in degrees (any sequence or numpy array), ``point`` on the axis
    (three numbers in the case's length unit; default the origin), ``analytic`` (3D only: the
    analytic interaction instead of FE), ``surface_radius`` (3D FE: the stress sphere's
    radius in the case's length unit; default mid-gap). Translate sweeps (axisymmetric
    cases): ``translate`` names the group moved along z, ``positions`` in mm (as the command
    line's --positions). FE positions take ``order`` (1 or 2; None: as in the case) and
    ``mesh_scale``. ``jobs``: positions at once (None: one per core).

    ``progress``: None, True (a "position i/n done" line on stderr per position) or a
    callable ``progress(done, total)``, called on the calling thread. The GIL is released
    while positions run. Ctrl-C (or an exception raised by ``progress``) starts no further
    position: those under way finish, then KeyboardInterrupt (or that exception) is raised.
    Raises InputError for a bad argument or a case the sweep cannot move; a failed position
    is not an exception (see ``SweepResult.failed`` and ``positions``).
    """
    request = _core.SweepRequest()
    if rotate is not None and translate is not None:
        raise _argument_error("rotate", "give one of rotate= (a group to turn) and translate= "
                              "(a group to move)")
    if translate is not None:
        request.translate = str(translate)
        values, field = positions, "positions"
        if angles is not None:
            raise _argument_error("angles", "translate sweeps take positions= (mm)")
    else:
        request.rotate = "" if rotate is None else str(rotate)
        values, field = angles, "angles"
        if positions is not None:
            raise _argument_error("positions", "rotating sweeps take angles= (degrees)")
    if values is None:
        raise _argument_error(field, "give the %s" % field)
    request.values = [float(v) for v in np.asarray(values, dtype=float).ravel()]
    request.axis = _axis_text(axis)
    request.analytic = bool(analytic)
    if point is not None:
        request.point = [float(v) for v in np.asarray(point, dtype=float).ravel()]
    if surface_radius is not None:
        request.surface_radius = float(surface_radius)
    request.jobs = _count("jobs", jobs)
    request.order = _count("order", order)
    request.mesh_scale = float(mesh_scale)
    out = _core.sweep(case._path or "", case._text or "", case._name or "", case._params,
                      request, progress)
    return SweepResult(out["columns"], json.loads(out["summary"]))
