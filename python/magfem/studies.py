"""magfem.sweep (and the other studies): the command line's studies in-process, their tables
as numpy columns (the compiled part is _core.sweep)."""
import json
import numbers
import os

import numpy as np

from . import _core


def _argument_error(field, message, call="<sweep>"):
    """An InputError about an argument of a study call ("<sweep>: field: message")."""
    err = _core._InputError("%s: %s: %s" % (call, field, message))
    err.file, err.line, err.field = call, None, field
    return err


def _count(name, value):
    """None -> 0 (the library's "as many as cores" / "as in the case"), else a positive int."""
    if value is None:
        return 0
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
        raise _argument_error(name, "must be a positive integer, not %r" % (value,))
    return int(value)


def _checkpoint(checkpoint_dir, resume):
    """The checkpoint_dir and resume arguments for the compiled call."""
    request = _core.CheckpointRequest()
    if checkpoint_dir is not None:
        request.dir = os.fspath(checkpoint_dir)
    request.resume = bool(resume)
    return request


_CHECKPOINT_DOC = """
    ``checkpoint_dir``, ``resume`` (as the command line's ``--out DIR`` and ``--resume``):
    with a directory, every finished %(item)s is kept in
    ``checkpoint_dir/.magfem-checkpoint.jsonl`` as it finishes (the command line's file;
    nothing else is written there). A call stopped by Ctrl-C, an exception of ``progress``,
    kill or a crash leaves it; the same call with ``resume=True`` restores those %(item)ss
    and runs the rest (failed ones again), giving the same table to the last bit. A
    checkpoint of another case, other parameter overrides or other options is refused
    (InputError, field ``resume``, the command line's message); without one, resume starts
    from the beginning. The call removes the checkpoint once its result is complete."""


def _document_checkpoint(function, item):
    """Appends the checkpoint arguments' text to a study call's docstring (none under -OO)."""
    if function.__doc__:
        function.__doc__ += _CHECKPOINT_DOC % {"item": item}


class _Table(dict):
    """A result table: a dict of numpy columns in the command line's CSV order."""

    @property
    def columns(self):
        """The column names, in the CSV's order."""
        return list(self.keys())

    def csv(self):
        """The CSV as the command line writes it (ten significant digits; NaN, an error
        without an estimate, as an empty cell)."""
        lines = [",".join(self.columns)]
        for row in zip(*self.values()):
            lines.append(",".join("" if np.isnan(v) else "%.10g" % v for v in row))
        return "\n".join(lines) + "\n"


class SweepResult(_Table):
    """A sweep's table: a dict of numpy columns named as the command line's sweep.csv
    (``angle_deg, Tx, Ty, Tz, Fx, Fy, Fz`` for rotating sweeps, N m and N; ``position_mm, Tx,
    ..., Fz`` for 3D and planar translate sweeps; ``position_mm, Fz_N`` for axisymmetric ones), successful
    positions only, in the order given.

    ``summary``: summary.json as ``magfem sweep`` writes it, but the provenance and the peak
    memory; ``method``, ``positions`` (per position: ok, seconds, error, ...) and ``failed``
    (the number of failed positions) are taken from it. ``csv()`` is sweep.csv's text."""

    def __init__(self, columns, summary):
        super().__init__(columns)
        self.summary = summary
        self.method = summary["method"]
        self.positions = summary["positions"]
        self.failed = summary["failed_positions"]

    def __repr__(self):
        return "<magfem.SweepResult %s: %d positions, %d failed>" % (
            self.method, len(self.positions), self.failed)


def _whole_number(name, value, call):
    """None, or an int (not a bool, not 2.5: the compiled call would truncate or refuse it
    with a TypeError rather than the command line's message)."""
    if value is not None and (isinstance(value, bool)
                              or not isinstance(value, numbers.Integral)):
        raise _argument_error(name, "must be a whole number >= 1, not %r" % (value,), call)
    return None if value is None else int(value)


def _axis_text(axis):
    if axis is None:
        return ""
    if isinstance(axis, str):
        return axis
    a = np.asarray(axis, dtype=float).ravel()
    if a.size not in (2, 3):  # two: a direction in a planar case's plane
        raise _argument_error("axis", "x, y, z or three numbers (two in a planar case), not %r"
                              % (axis,))
    return ",".join(repr(float(x)) for x in a)


def sweep(case, rotate=None, axis=None, angles=None, analytic=False, jobs=None, progress=None,
          *, translate=None, positions=None, point=None, surface_radius=None, order=None,
          mesh_scale=1.0, checkpoint_dir=None, resume=False):
    """Runs ``magfem sweep`` on a Case in-process and returns a SweepResult (numpy columns).

    Rotating sweeps (3D and planar 2D cases): ``rotate`` names the group to turn, ``axis``
    ("x", "y", "z" or three numbers; None: "y" in 3D, "z" for planar cases, which turn about
    z only), ``angles`` in degrees (any sequence or numpy array), ``point`` on the axis
    (three numbers in the case's length unit; default the origin), ``analytic`` (3D only: the
    analytic interaction instead of FE), ``surface_radius`` (3D FE: the stress sphere's
    radius in the case's length unit; default mid-gap). Translate sweeps: ``translate`` names
    the group moved, ``positions`` its offsets in mm (as the command line's --positions);
    axisymmetric cases move it along z (FE, force Fz), 3D cases along ``axis`` (required; FE
    or ``analytic``; the rotating sweep's columns with ``position_mm`` first), planar cases
    along ``axis`` in their plane ("x", "y" or two numbers; FE; the same columns, force per
    metre, Tz about ``point`` carried with the group). FE positions take ``order`` (1 or 2;
    None: as in the case) and ``mesh_scale``. ``jobs``: positions at once (None: one per
    core).

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
    request.checkpoint = _checkpoint(checkpoint_dir, resume)
    out = _core.sweep(case._path or "", case._text or "", case._name or "", case._params,
                      request, progress)
    return SweepResult(out["columns"], json.loads(out["summary"]))


_document_checkpoint(sweep, "position")


class StudyResult(_Table):
    """A study's table: a dict of numpy columns named as the command line's study.csv (one per
    parameter, in the order given, then one per objective: ``peak_torque_Nm``,
    ``torque_at_90deg_Nm``, N m; FE studies then each objective's estimated error,
    ``peak_torque_Nm_err``, N m, NaN where there is none), successful designs only, the last
    parameter varying fastest.

    ``summary``: summary.json as ``magfem study`` writes it, but the provenance; ``method``
    and ``failed`` (the number of failed designs) are taken from it, ``failures`` lists each
    failed design's parameters and error, ``adapt`` each FE design that refined its mesh
    (parameters, converged, passes, unknowns, estimated_error_pct, stopped_deg; empty
    otherwise) and ``warnings`` those that stopped at a limit first. ``csv()`` is study.csv's
    text, byte for byte the command line's."""

    def __init__(self, columns, summary):
        super().__init__(columns)
        self.summary = summary
        self.method = summary["method"]
        self.failed = summary["failed_designs"]
        self.failures = summary.get("failures", [])
        self.adapt = summary.get("adapt", [])
        self.warnings = summary.get("warnings", [])

    def __repr__(self):
        return "<magfem.StudyResult %s: %d designs, %d failed>" % (
            self.method, self.summary["designs"], self.failed)


def study(case, params, objectives, rotate, axis, angles=None, analytic=True, jobs=None,
          progress=None, *, order=None, mesh_scale=1.0, accuracy=None, max_passes=None,
          max_unknowns=None, checkpoint_dir=None, resume=False):
    """Runs ``magfem study`` on a Case in-process and returns a StudyResult (numpy columns).

    ``params``: {name: values} over the case's parameters (values in the parameter's own
    unit, any sequence or numpy array; the grid of all combinations, the last name varying
    fastest, as repeated --param). ``objectives``: names as --objective (``"peak_torque"``,
    ``"torque_at:DEG"``), a string or a list. ``rotate``, ``axis``, ``angles`` (degrees; needed
    by peak_torque) as in ``sweep``; ``analytic`` True (the default, as the command line) or
    False for FE designs with ``order`` and ``mesh_scale``; ``jobs``: positions at once.
    FE: ``accuracy`` (percent), ``max_passes``, ``max_unknowns`` as the command line's
    --accuracy, --max-passes, --max-unknowns (None: the case's ``adapt:``): every position a
    design's objectives need refines its mesh for its torque; a design that stops at a limit
    first is listed in ``warnings``, its ``_err`` columns the estimates reached. Given with
    ``analytic=True`` they raise InputError.
    ``progress``: None, True (a line per design) or ``progress(done, total)`` per design; the
    GIL is released meanwhile; Ctrl-C starts no further design and raises KeyboardInterrupt.
    A design whose case cannot be read or solved is recorded (``failed``, ``failures``), not
    raised; a bad argument, parameter name or group raises InputError.
    """
    request = _core.StudyRequest()
    if not isinstance(params, dict) or not params:
        raise _argument_error("params", "a dict {parameter: values}, not %r" % (params,),
                              "<study>")
    request.parameters = [(str(k), [float(v) for v in np.asarray(vals, dtype=float).ravel()])
                          for k, vals in params.items()]
    request.objectives = [objectives] if isinstance(objectives, str) else list(objectives)
    request.rotate = str(rotate)
    request.axis = _axis_text(axis)
    if angles is not None:
        request.angles = [float(v) for v in np.asarray(angles, dtype=float).ravel()]
    request.analytic = bool(analytic)
    request.jobs = _count("jobs", jobs)
    request.order = _count("order", order)
    request.mesh_scale = float(mesh_scale)
    request.accuracy = None if accuracy is None else float(accuracy)
    request.max_passes = _whole_number("max_passes", max_passes, "<study>")
    request.max_unknowns = None if max_unknowns is None else float(max_unknowns)
    request.checkpoint = _checkpoint(checkpoint_dir, resume)
    out = _core.study(case._path or "", case._text or "", case._name or "", case._params,
                      request, progress)
    return StudyResult(out["columns"], json.loads(out["summary"]))


_document_checkpoint(study, "design")


class ActuatorResult:
    """``magfem actuator``'s tables as numpy arrays (returned by magfem.actuator).

    ``coils`` (names, the columns' order), ``resistance_ohm`` (per coil),
    ``orientations_deg`` (n x 3: rx, ry, rz; R = Rz(rz) Ry(ry) Rx(rx)), ``gamma`` (n x 3 x
    coils: the torque constants, N m/A, torque_constants.csv's kx, ky, kz per coil),
    ``commutations``: demand name ("T_d", or "P_x", "P_y", "P_z" for the unit torques) ->
    dict with ``torque_Nm`` (3,), ``currents_A`` (n x coils), ``P_W``, ``i_peak_A``,
    ``cond_Gamma`` and ``ok`` (n,), as the commutation CSVs (NaN where an ill-conditioned
    row leaves the cell empty); ``method`` ("charge_model" or "fe"), ``n_field_solves``,
    ``notes``."""

    def __init__(self, d):
        self.method = d["method"]
        self.coils = list(d["coils"])
        self.resistance_ohm = d["resistance_ohm"]
        self.orientations_deg = d["orientations_deg"]
        self.gamma = d["gamma"]
        self.commutations = dict(d["commutations"])
        self.n_field_solves = d["n_field_solves"]
        self.notes = list(d["notes"])

    def __repr__(self):
        return "<magfem.ActuatorResult %s: %d orientations x %d coils>" % (
            self.method, len(self.orientations_deg), len(self.coils))


def _orientation_rows(orientations, call):
    """An n x 3 array of (rx, ry, rz) in degrees as a list of tuples."""
    rows = np.asarray(orientations, dtype=float)
    if rows.ndim != 2 or rows.shape[1] != 3:
        raise _argument_error("orientations", "an n x 3 array of (rx, ry, rz) in degrees "
                              "or the command line's text, not shape %s" % (rows.shape,), call)
    return [tuple(float(x) for x in r) for r in rows]


def actuator(case, rotor, orientations, analytic=True, torque=None, *, order=None,
             mesh_scale=1.0, progress=None):
    """Runs ``magfem actuator`` on a Case in-process; returns an ActuatorResult.

    ``rotor``: the rotor's group. ``orientations``: the command line's --orientations text
    ("rx=-45:15:45,ry=0,rz=0", or a CSV file with rx_deg,ry_deg,rz_deg) or an n x 3 array of
    (rx, ry, rz) in degrees. ``torque``: the demanded torque (3 numbers, N m; None: the unit
    torques about x, y and z, the thesis's power study). ``analytic``: the charge model
    (True) or FE (False; ``order``, ``mesh_scale`` and ``progress`` as in Case.solve, whose
    Ctrl-C handling the FE solves share). The GIL is released meanwhile. Raises InputError.
    """
    request = _core.ActuatorRequest()
    request.rotor = str(rotor)
    if isinstance(orientations, str):
        request.orientations_text = orientations
    else:
        request.orientations = _orientation_rows(orientations, "<actuator>")
    if torque is not None:
        t = np.asarray(torque, dtype=float).ravel()
        if t.size != 3:
            raise _argument_error("torque", "three numbers (N m)", "<actuator>")
        request.torque_Nm = tuple(float(x) for x in t)
    request.analytic = bool(analytic)
    request.order = _count("order", order)
    request.mesh_scale = float(mesh_scale)
    return ActuatorResult(_core.actuator(case._path or "", case._text or "", case._name or "",
                                         case._params, request, progress))


class CoilPitchResult(_Table):
    """The coil-pitch study's table (returned by magfem.coil_pitch): a dict of numpy columns
    named as the command line's coil_pitch.csv, one row per pitch: ``coil_pitch_deg``,
    ``n_coils`` (int), ``G_w_deg``, ``C_w_deg`` (the coils' gap and width), ``P_x_W``,
    ``P_y_W``, ``P_z_W`` (mean copper loss over the orientations for 1 N m about x, y, z),
    ``P_mean_W`` (their average) and ``n_ill_x``, ``n_ill_y``, ``n_ill_z`` (int: orientations
    left out, Gamma ill-conditioned).

    ``summary``: summary.json as ``magfem actuator --coil-pitch`` writes it, but its wall time
    ``seconds``; ``minimum`` (the row of least ``P_mean_W``: coil_pitch_deg, n_coils,
    P_mean_W, P_x_W, P_y_W, P_z_W) and ``notes`` are taken from it. ``csv()`` is
    coil_pitch.csv's text, byte for byte the command line's."""

    def __init__(self, run):
        super().__init__(run.columns())
        self._csv = run.csv()
        self.summary = json.loads(run.summary_json())
        self.minimum = self.summary["minimum"]
        self.notes = list(self.summary["notes"])

    def csv(self):
        """coil_pitch.csv's text, as the command line writes it (ten significant digits)."""
        return self._csv

    def __repr__(self):
        return "<magfem.CoilPitchResult %d pitches: least P_mean %.4g W at %g deg>" % (
            len(self["coil_pitch_deg"]), self.minimum["P_mean_W"],
            self.minimum["coil_pitch_deg"])


def coil_pitch(case, rotor, orientations, pitches, *, coil_quadrature=None):
    """Runs the thesis's coil-pitch study (``magfem actuator --analytic --coil-pitch``,
    sec. 5.3) on a Case in-process; returns a CoilPitchResult.

    The case's coils are replaced, pitch by pitch, by the thesis's circular-coil array
    (sized from the case's first coil); for each pitch, the mean copper loss over the
    orientations of the minimum-loss currents for 1 N m about x, y and z, by the charge
    model. ``rotor``: the rotor's group. ``orientations``: as in ``actuator`` (the command
    line's --orientations text or an n x 3 array of (rx, ry, rz) in degrees). ``pitches``:
    the command line's --coil-pitch text ("40:1:70", degrees) or a sequence of pitches in
    degrees. ``coil_quadrature``: the rule over each coil, the command line's
    --coil-quadrature (N_R, N_ALPHA, ALPHA_PANELS, N_AZIMUTH), four integers or their text
    (None: 4, 3, 2, 32; the rotor's field is tabulated on N_R spheres, most of the time).
    A function of its own rather than an argument of ``actuator``: its table (one
    row per pitch) is not actuator's, and its demand (unit torques) and model (the charge
    model) are fixed. The arguments are checked by the command line's own checks, with its
    messages (field: the argument's name). The GIL is released meanwhile; the study is not
    interrupted by Ctrl-C (it takes seconds). Raises InputError.
    """
    request = _core.CoilPitchRequest()
    request.rotor = str(rotor)
    if isinstance(pitches, str):
        request.pitches = pitches
    else:
        values = np.asarray(pitches, dtype=float).ravel()
        request.pitches = ",".join(repr(float(v)) for v in values)
    if isinstance(orientations, str):
        request.orientations_text = orientations
    else:
        request.orientations = _orientation_rows(orientations, "<coil_pitch>")
    if coil_quadrature is not None:
        request.coil_quadrature = (coil_quadrature if isinstance(coil_quadrature, str) else
                                   ",".join(str(n) for n in coil_quadrature))
    return CoilPitchResult(_core.coil_pitch(case._path or "", case._text or "",
                                            case._name or "", case._params, request))


class ValidationResult:
    """``magfem validate``'s results (returned by magfem.validate): ``rows``, one dict per
    entry as results.json's "entries" (id, source, quantity, unit, published, fe, analytic,
    tolerance_pct, the errors, status, seconds, method, details, ...), ``summary`` (status
    -> count), ``tier``, ``catalogue``, ``failed`` (ids of failed entries) and ``table()``
    (numpy columns of the numeric results.csv columns)."""

    def __init__(self, results):
        self.rows = results["entries"]
        self.summary = results["summary"]
        self.tier = results["tier"]
        self.catalogue = results["catalogue"]
        self.failed = [r["id"] for r in self.rows if r["status"] == "fail"]

    def table(self):
        """id and status as lists; published, fe, analytic, tolerance_pct, fe_error_pct,
        analytic_error_pct, seconds, passes and unknowns as numpy arrays (NaN where an entry
        has none: passes for an FE value solved to an accuracy only) and converged as a list
        (True, False, or None for no adaptive FE value), as in results.csv."""
        out = {"id": [r["id"] for r in self.rows], "status": [r["status"] for r in self.rows]}
        for key in ("published", "fe", "analytic", "tolerance_pct", "fe_error_pct",
                    "analytic_error_pct", "seconds", "passes", "unknowns"):
            out[key] = np.array([np.nan if r[key] is None else r[key] for r in self.rows])
        out["converged"] = [r.get("converged") for r in self.rows]
        return out

    def __repr__(self):
        return "<magfem.ValidationResult %s: %s>" % (self.tier, self.summary)


def validate(tier="quick", entries=None, source=None, jobs=None, progress=None,
             catalogue=None, *, checkpoint_dir=None, resume=False):
    """Runs ``magfem validate`` in-process (no report written); returns a ValidationResult.

    ``tier``: "quick" or "full"; ``entries``: catalogue ids (as --only; None: all of the
    tier), or ``source``: a seed file prefix (as --source); ``jobs``: entries at once (None:
    one per core); ``catalogue``: another catalogue file (None: the installed or source
    tree's validation/catalogue.yaml). ``progress``: None, True or ``progress(done, total)``
    on the calling thread; Ctrl-C starts no further entry and raises KeyboardInterrupt, as
    in sweep(). A failed entry is a row with status "fail", not an exception.
    """
    if isinstance(entries, str):
        entries = [entries]
    out = _core.validate(str(tier), [str(e) for e in entries or []], source or "",
                         _count("jobs", jobs), str(catalogue or ""),
                         _checkpoint(checkpoint_dir, resume), progress)
    return ValidationResult(json.loads(out))


_document_checkpoint(validate, "entry")
