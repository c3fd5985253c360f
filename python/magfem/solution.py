"""magfem.Solution: a solved case as Python reads it (the compiled part is _core.Solution)."""
import json

import numpy as np

# Metres per unit of the points given to Solution.B / Solution.H.
_UNITS = {"m": 1.0, "mm": 1e-3}


def _numpy_vectors(value):
    """JSON from the C++ writers with its 3-vectors (force_N, torque_Nm, ...) as numpy."""
    if isinstance(value, dict):
        return {k: _numpy_vectors(v) for k, v in value.items()}
    if isinstance(value, list) and len(value) == 3 and all(
            isinstance(x, (int, float)) for x in value):
        return np.array(value, dtype=float)
    if isinstance(value, list):
        return [_numpy_vectors(v) for v in value]
    return value


class Mesh:
    """The linear mesh of a solution (higher-order nodes live in the solver, not here).

    ``nodes``: (n, 2) in metres for 2D (x, y; r, z when axisymmetric), (n, 3) for 3D.
    ``elements``: (m, 3) triangles or (m, 4) tetrahedra, indices into ``nodes``.
    ``regions``: (m,) the case's region index of each element; -1 background air, -2 the
    exterior shell of an open boundary. ``region_names``: the case's regions in order.
    """

    def __init__(self, d):
        self.nodes = d["nodes"]
        self.elements = d["elements"]
        self.regions = d["regions"]
        self.region_names = list(d["region_names"])

    def __repr__(self):
        return "<magfem.Mesh: %d nodes, %d elements>" % (len(self.nodes), len(self.elements))


class _Result:
    """What FE and analytic answers share: forces, probes, summary.json, write."""

    def __init__(self, core):
        self._core = core
        self._summary = None

    @property
    def forces(self):
        """name -> dict: ``force_N`` and ``torque_Nm`` (numpy vectors), ``method``, and the
        check-surface and error-estimate entries when the run has them (summary.json's)."""
        return {f["name"]: _numpy_vectors(f) for f in json.loads(self._core.forces_json())}

    @property
    def probes(self):
        """name -> dict of numpy columns, as the probe CSV files (case length unit, T)."""
        return self._core.probes()

    @property
    def summary(self):
        """summary.json as the command line writes it (timings and provenance included)."""
        if self._summary is None:
            self._summary = json.loads(self._core.summary_json())
        return self._summary

    def write(self, out_dir):
        """Writes what the command line's ``--out out_dir`` writes (summary.json, probe CSVs,
        forces.csv, the VTU of an FE solution, ...), all-or-nothing; returns the file
        names."""
        return self._core.write(str(out_dir))


class AnalyticSolution(_Result):
    """A case answered by the analytic models (returned by magfem.analytic): ``forces``,
    ``coils``, ``inductance_H``, ``probes``, ``summary`` and ``write(dir)``, as ``magfem
    analytic`` writes them. No field at arbitrary points: give the case probes."""

    @property
    def coils(self):
        """name -> dict (summary.json's "coils": linkage, force and torque where known)."""
        return {c["name"]: _numpy_vectors(c) for c in self.summary.get("coils", [])}

    @property
    def inductance_H(self):
        """Numpy matrix in the order of ``coils``, or None when not computable."""
        l = self.summary.get("inductance_H")
        return None if l is None else np.array(l["matrix"], dtype=float)

    def __repr__(self):
        return "<magfem.AnalyticSolution: %s>" % self.summary.get("model")


def _adapt_estimates(adapt):
    """quantity -> {"value", "error_pct"} of the last pass of summary.json's adapt block (the
    loop's stopping test: the estimator's for energy, the extrapolated change for the others;
    None where not known yet, i.e. after a single pass)."""
    last = adapt["passes"][-1]
    # The energy's estimate always counts (an accuracy without quantities stops on it alone).
    out = {"energy": {"value": last["energy_J"], "error_pct": last["energy_error_pct"]}}
    out.update({q: {"value": v, "error_pct": last["quantity_error_pct"][q]}
                for q, v in last["quantities"].items()})
    return out


class Solution(_Result):
    """A solved case (returned by Case.solve); everything is in SI units.

    ``energy`` (J; 2D planar: J/m, or J for the stack when the case gives one),
    ``energy_error_pct`` (the estimated relative error of ``energy``, %), ``adapt`` (the passes
    of an adaptive solve, else None), ``probe_error_pct`` (adaptive solves: probe -> the
    estimated error of its rms field, %),
    ``forces`` (name -> dict with ``force_N``, ``torque_Nm`` numpy vectors, the method, and
    the check-surface and error-estimate entries when the run has them), ``coils`` (name ->
    dict: turns, current_A, flux_linkage_Wb, ...), ``inductance_H`` (numpy matrix in the
    order of ``coils``, 3D and axisymmetric coils, else None), ``probes`` (name -> dict of
    numpy columns, as the CSV files), ``summary`` (summary.json as a dict), ``mesh`` (Mesh), ``B(points)``,
    ``H(points)`` and ``write(dir)``.
    """

    def __init__(self, core):
        super().__init__(core)
        self.dimension = core.dimension
        """"2d" (planar), "axi" (axisymmetric) or "3d"."""
        self.energy = core.energy_J
        self._mesh = None

    @property
    def energy_error_pct(self):
        """The estimated relative error of ``energy`` in percent (summary.json's
        error_estimate.energy_error_pct: 100 eta^2 / (2 W), every solve has it)."""
        return self.summary["error_estimate"]["energy_error_pct"]

    @property
    def adapt(self):
        """The adaptive loop of a solve with an accuracy (``Case.solve(accuracy=...)`` or the
        case's ``adapt:`` section), else None: summary.json's ``adapt`` block (accuracy_pct,
        converged, stop_reason when not converged, passes: one dict per pass) and
        ``estimates``: quantity ("energy", "forces.NAME.COMPONENT", "probes.NAME") ->
        {"value", "error_pct"} at the last pass, the figures the loop stopped on."""
        adapt = self.summary.get("adapt")
        if adapt is None:
            return None
        return {**adapt, "estimates": _adapt_estimates(adapt)}

    @property
    def forces(self):
        """name -> dict: ``force_N`` and ``torque_Nm`` (numpy vectors), ``method``, the
        check-surface and ``error_estimate`` entries when the run has them (summary.json's),
        and, in an adaptive solve naming components of the force as quantities,
        ``error_pct``: component ("Fx" .. "Tz", "force", "torque") -> its estimated error (%)
        at the last pass (None after a single pass)."""
        forces = super().forces
        adapt = self.summary.get("adapt")
        for quantity, e in (_adapt_estimates(adapt) if adapt else {}).items():
            kind, _, rest = quantity.partition(".")
            name, _, component = rest.rpartition(".")
            if kind == "forces" and name in forces:
                forces[name].setdefault("error_pct", {})[component] = e["error_pct"]
        return forces

    @property
    def probe_error_pct(self):
        """Adaptive solves naming probes as quantities: probe name -> the estimated error (%)
        of its rms field at the last pass (None after a single pass); else empty."""
        adapt = self.summary.get("adapt")
        return {q[len("probes."):]: e["error_pct"]
                for q, e in (_adapt_estimates(adapt) if adapt else {}).items()
                if q.startswith("probes.")}

    @property
    def coils(self):
        """name -> dict: turns, current_A, flux_linkage_Wb, inductance_H (d lambda / dI, the
        differential inductance) and linkage_per_ampere_H (lambda / I, the apparent one,
        with the magnets' flux); resistance_ohm, power_W, force_N, torque_Nm in 3D."""
        return {c["name"]: _numpy_vectors(c) for c in json.loads(self._core.coils_json())}

    @property
    def inductance_H(self):
        """The inductance matrix (H, differential) in the order of ``coils`` (3D and
        axisymmetric coils), or None when the run did not compute one."""
        return self._core.inductance_H()

    @property
    def mesh(self):
        """The linear mesh as numpy arrays (Mesh: nodes, elements, regions, region_names)."""
        if self._mesh is None:
            self._mesh = Mesh(self._core.mesh())
        return self._mesh

    def _field(self, points, unit, outside, want_h):
        if unit not in _UNITS:
            raise ValueError("unit must be one of %s, not %r" % (sorted(_UNITS), unit))
        if outside not in ("raise", "nan"):
            raise ValueError("outside must be 'raise' or 'nan', not %r" % (outside,))
        p = np.asarray(points, dtype=float)
        single = p.ndim == 1
        p = np.atleast_2d(p)
        if p.ndim != 2 or p.shape[1] != 3:
            raise ValueError("points must be N x 3 (x, y, z), got shape %s" % (p.shape,))
        v = self._core.field_at(p * _UNITS[unit], want_h)
        if outside == "raise":
            lost = np.flatnonzero(np.isnan(v[:, 0]))
            if lost.size:
                raise ValueError(
                    "%d point(s) outside the meshed domain, the first: index %d at %s %s "
                    "(outside='nan' gives NaN there)" % (lost.size, lost[0], p[lost[0]], unit))
        return v[0] if single else v

    def B(self, points, unit="m", outside="raise"):
        """Flux density (T) at points: an N x 3 array (or one point) of Cartesian x, y, z in
        ``unit`` ("m" or "mm"); returns N x 3 (Bx, By, Bz).

        Planar cases ignore z (Bz = 0); axisymmetric cases are about the z axis (a point
        (r, 0, z) gives (Br, 0, Bz)). 2D: the field of the element holding the point, as the
        probe CSVs; 3D: the recovered B of the point's region, as the probe CSVs. Points
        outside the meshed physical domain (the shell of an open boundary included) raise
        ValueError, or give NaN rows with ``outside="nan"``.
        """
        return self._field(points, unit, outside, False)

    def H(self, points, unit="m", outside="raise"):
        """Field strength (A/m) at points, as B(): from the element's constitutive law
        (remanence included), the element field also in 3D."""
        return self._field(points, unit, outside, True)

    def __repr__(self):
        return "<magfem.Solution %s: energy %.6g J>" % (self.dimension, self.energy)
