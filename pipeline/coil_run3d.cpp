#include "pipeline/coil_run3d.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "core/input_error.hpp"
#include "mesh/grid_frame3d.hpp"
#include "pipeline/inductance_matrix_output.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/coil_linkage3d.hpp"
#include "postproc/lorentz3d.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/current_sensitivity3d.hpp"
#include "sources/coil_field.hpp"

namespace magfem {

// The sensitivity solves stop at a relative residual of 1e-5 unless the case asks for a
// looser one. The inductance takes the variational correction (current_sensitivity3d.hpp), so
// its error is the product of two columns' energy-norm errors plus a term linear in them that
// the total-potential regions leave (their load K Phi_s is not exactly minus the functional's
// gradient). Measured on the 12-coil actuator design (mesh scale 3; the largest entry's
// relative error against solves to 1e-12): 1.6e-9 uncorrected at 1e-9 (the former
// tolerance); corrected 4e-11 at 1e-9, 5e-8 at 1e-6, 3.4e-7 at 1e-5, 4.4e-6 at 1e-4. 1e-5
// stays below 1e-6, below the matrix's own asymmetry (7e-6, a discretization effect) and far
// below its discretization error, and takes 12 block CG iterations against 28 at 1e-9.
LinearSolverOptions sensitivity_solver_options(LinearSolverOptions options) {
  options.cg_tolerance = std::max(options.cg_tolerance, 1e-5);
  return options;
}

// Under mpirun the same relative residual can leave a larger error in the energy norm: the
// preconditioner differs from the serial one (bounded cases: block Jacobi across processes,
// and the coarse level's BoomerAMG on a partitioned matrix). At 1e-5 the coil case and TEAM 20
// on 3 processes were 1.6e-6 and 5.5e-6 of the inductance off the serial run
// (tests/cli/test_mpi_solve.cpp, whose bound is 1e-6); a decade tighter brings them back.
LinearSolverOptions distributed_sensitivity_solver_options(LinearSolverOptions options) {
  options.cg_tolerance = std::max(options.cg_tolerance, 1e-6);
  return options;
}

namespace {

// Gauss order of the coil volume quadrature for the Lorentz force: B is smooth across the
// bundle (its own field is subtracted), so a few points per direction suffice there. Along a
// ring coil's azimuth it is not: a multipole magnet array under the coil puts high harmonics
// on the ring, and 12 azimuths (2 x order) left 1 % of the largest torque in a component that
// symmetry makes zero (a 6-coil actuator over a 2 x 4 segment array); 64 take it below the
// FE's own error.
constexpr int lorentz_order = 6;
constexpr int lorentz_azimuths = 64;

std::vector<CoilVolumePoint> volume_points(const CaseCoils& coils, int k, int order) {
  std::vector<CoilVolumePoint> out;
  for (const auto& q : coils.field(k).volume_quadrature(order, lorentz_azimuths))
    out.push_back({q.x, q.weight, coils.current(k) * q.j_per_ampere});
  return out;
}

int coil_index(const Run3D& run, const std::string& name) {
  const auto& coils = run.spec.geometry3d.coils;
  for (std::size_t k = 0; k < coils.size(); ++k)
    if (coils[k].name == name)
      return static_cast<int>(k);
  throw std::logic_error("no coil named " + name);
}

// Every coil's volume quadrature for the Lorentz integrals, with one locator over the tets
// that reach into the points' bounding box (a whole-mesh locator indexes all 1.6 M tets of
// benchmark32; the coils' box holds a fraction of them).
class CoilQuadrature {
public:
  explicit CoilQuadrature(const Run3D& run)
      : points_(all_points(*run.coils)), locator_(run.mesh, positions(points_)) {}
  const std::vector<CoilVolumePoint>& points(int coil) const { return points_[coil]; }
  const PointLocator3D& locator() const { return locator_; }

  // The sum over a Lorentz force's coils of integrate(coil index) (a ForceTorque).
  template <class Integrate>
  ForceTorque sum(const Run3D& run, const ForceSpec& f, const Integrate& integrate) const {
    ForceTorque total;
    for (const auto& name : f.regions) {
      const ForceTorque ft = integrate(coil_index(run, name));
      total.force += ft.force;
      total.torque += ft.torque;
    }
    return total;
  }

private:
  static std::vector<std::vector<CoilVolumePoint>> all_points(const CaseCoils& coils) {
    std::vector<std::vector<CoilVolumePoint>> out;
    for (int k = 0; k < coils.n_coils(); ++k)
      out.push_back(volume_points(coils, k, lorentz_order));
    return out;
  }
  static std::vector<Eigen::Vector3d>
  positions(const std::vector<std::vector<CoilVolumePoint>>& points) {
    std::vector<Eigen::Vector3d> out;
    for (const auto& coil : points)
      for (const auto& q : coil)
        out.push_back(q.x);
    return out;
  }
  std::vector<std::vector<CoilVolumePoint>> points_;
  PointLocator3D locator_;
};

} // namespace

CoilFieldOptions fe_source_options() {
  CoilFieldOptions o;
  o.tolerance = 1e-4;
  o.near_order = 4;
  return o;
}

// Points memoised per run: ~56 bytes of key and index plus 24 per coil, at most
// coil_field_cache_limit_mb in all. (A cap of 16 M points, meant as 1.3 GB for one coil,
// let 12 coils take 2.9 GB on a 423k-tetrahedron actuator, 3x the rest of the run.)
std::size_t max_cached_points(std::size_t n_coils) {
  return static_cast<std::size_t>(coil_field_cache_limit_mb * 1024 * 1024) / (56 + 24 * n_coils);
}

CaseCoils::CaseCoils(const std::vector<Coil3D>& coils, const CoilFieldOptions& options)
    : coils_(coils), cache_(static_cast<int>(coils.size()), max_cached_points(coils.size())) {
  for (const auto& c : coils_)
    fields_.push_back(std::make_unique<CoilField>(c, options));
}

CaseCoils::~CaseCoils() = default;

void CaseCoils::H_per_ampere_all(const Eigen::Vector3d& x, Eigen::Vector3d* out) const {
  cache_.get(
      x, [this](const Eigen::Vector3d& p, Eigen::Vector3d* h) { H_per_ampere_all_once(p, h); },
      out);
}

void CaseCoils::H_per_ampere_all_once(const Eigen::Vector3d& x, Eigen::Vector3d* out) const {
  for (std::size_t k = 0; k < fields_.size(); ++k)
    out[k] = fields_[k]->H_per_ampere(x);
}

namespace {

// The per-point queries run at every quadrature point of several passes: a buffer on the
// stack for the usual coil counts instead of a heap allocation per call.
template <class Use>
auto with_all_per_ampere(const CaseCoils& coils, const Eigen::Vector3d& x, const Use& use) {
  constexpr int on_stack = 32;
  const int nc = coils.n_coils();
  if (nc <= on_stack) {
    std::array<Eigen::Vector3d, on_stack> h;
    coils.H_per_ampere_all(x, h.data());
    return use(h.data());
  }
  std::vector<Eigen::Vector3d> h(nc);
  coils.H_per_ampere_all(x, h.data());
  return use(h.data());
}

} // namespace

Eigen::Vector3d CaseCoils::H(const Eigen::Vector3d& x) const {
  return with_all_per_ampere(*this, x, [this](const Eigen::Vector3d* h) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < fields_.size(); ++k)
      sum += coils_[k].current * h[k];
    return sum;
  });
}

Eigen::Vector3d CaseCoils::H_per_ampere(int coil, const Eigen::Vector3d& x) const {
  return with_all_per_ampere(*this, x, [coil](const Eigen::Vector3d* h) { return h[coil]; });
}

Eigen::Vector3d CaseCoils::J(const Eigen::Vector3d& x) const {
  Eigen::Vector3d j = Eigen::Vector3d::Zero();
  for (const auto& f : fields_)
    j += f->current_density(x);
  return j;
}

void check_coils_in_air(const CaseSpec& spec, const CaseCoils& coils) {
  const Geometry3D& g = spec.geometry3d;
  // Strict interiors: a coil wound tightly on a core (its r_inner on the core's surface) is
  // in air.
  const double tol = -1e-9 * g.outer.radius;
  for (int k = 0; k < coils.n_coils(); ++k) {
    const std::string field = "coils." + coils.coil(k).name;
    for (const auto& q : coils.field(k).volume_quadrature(4)) {
      if (q.x.norm() >= g.outer.radius)
        throw InputError(spec.file, spec.coil_lines[k], field,
                         "the coil leaves the meshed domain (boundary radius)");
      for (std::size_t part = 0; part < g.parts.size(); ++part) {
        // Air regions (mesh aids) may hold coils; magnets and iron may not.
        const Material* m = spec.regions[part].material;
        if (!(m->is_magnet() || m->is_nonlinear() || m->mu_r != 1.0))
          continue;
        if (part_contains(g.parts[part], q.x, tol))
          throw InputError(spec.file, spec.coil_lines[k], field,
                           "the coil overlaps region '" + spec.regions[part].name +
                               "'; coils must lie in air");
      }
    }
  }
}

CoilResults compute_coil_results(const Run3D& run, const Assembler3D& assembler,
                                 const Eigen::VectorXd& u) {
  CoilResults out;
  if (!run.coils)
    return out;
  const CaseCoils& coils = *run.coils;
  const int nc = coils.n_coils();
  const std::vector<double> linkage = flux_linkages_3d(*run.field);
  const CoilQuadrature quadrature(run);
  for (int k = 0; k < nc; ++k) {
    CoilResult r;
    const Coil3D& c = coils.coil(k);
    r.name = c.name;
    r.turns = c.turns;
    r.current_A = c.current;
    r.resistance_ohm = coils.field(k).resistance();
    r.power_W = r.resistance_ohm * c.current * c.current;
    r.flux_linkage_Wb = linkage[k];
    try {
      const ForceTorque ft = lorentz_force_3d(*run.field, quadrature.locator(), k,
                                              quadrature.points(k), Eigen::Vector3d::Zero());
      r.force_N = ft.force;
      r.torque_Nm = ft.torque;
    } catch (const std::invalid_argument& e) {
      throw InputError(run.spec.file, run.spec.coil_lines[k], "coils." + c.name, e.what());
    }
    out.coils.push_back(r);
  }
  if (run.spec.coil_inductance) {
    const auto t0 = std::chrono::steady_clock::now();
    // Distributed: solved on every process beforehand (run3d.cpp).
    const CurrentSensitivities3D sens =
        !run.coil_sensitivities.du.empty()
            ? run.coil_sensitivities
            : current_sensitivities_with_correction_3d(
                  assembler, u, nc, sensitivity_solver_options(run.spec.newton.linear),
                  run.report.factorized.get());
    std::vector<Eigen::VectorXd> full;
    for (const auto& s : sens.du)
      full.push_back(assembler.expand(s));
    out.inductance_H = inductance_matrix_3d(*run.field, full);
    out.inductance_H -= sens.correction;
    out.inductance_s = run.coil_sensitivity_s +
                       std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  out.warnings = run.coil_source.warnings;
  return out;
}

std::vector<ForceResult> coil_lorentz_forces(const Run3D& run) {
  std::vector<ForceResult> out;
  if (!run.coils)
    return out;
  const CoilQuadrature quadrature(run);
  for (const auto& f : run.spec.forces) {
    if (f.kind != ForceSpec::Kind::lorentz)
      continue;
    const ForceTorque ft = quadrature.sum(run, f, [&](int k) {
      return lorentz_force_3d(*run.field, quadrature.locator(), k, quadrature.points(k),
                              f.torque_point);
    });
    ForceResult r;
    r.name = f.name;
    r.method = "lorentz";
    r.force = ft.force;
    r.torque = ft.torque;
    out.push_back(r);
  }
  return out;
}

// Why the element field against the recovered one: both converge to the field of everything
// but the coil, and for the exact field the two integrals agree. The change between adaptive
// passes alone was not enough: on the small actuator it fell to 0.026 % by chance (two meshes'
// torques agreeing) while the torque was 0.14 % off the charge model's; the adaptive loop
// takes the larger of the change and this estimate (adapt_loop.cpp). The coils sit in air,
// so their patches are whole and B* is an order better than B_h there.
void estimate_lorentz_errors_3d(const Run3D& run, const PatchRecovery3D& recovery,
                                std::vector<ForceResult>& forces) {
  if (!run.coils)
    return;
  const CoilQuadrature quadrature(run);
  for (const auto& f : run.spec.forces) {
    if (f.kind != ForceSpec::Kind::lorentz)
      continue;
    const auto r = std::find_if(forces.begin(), forces.end(), [&](const ForceResult& x) {
      return x.name == f.name && x.method == "lorentz";
    });
    if (r == forces.end())
      continue;
    const ForceTorque recovered = quadrature.sum(run, f, [&](int k) {
      return lorentz_force_recovered_3d(recovery, quadrature.locator(), k, quadrature.points(k),
                                        f.torque_point);
    });
    r->estimated = true;
    r->force_err = (recovered.force - r->force).cwiseAbs();
    r->torque_err = (recovered.torque - r->torque).cwiseAbs();
    r->error_method = "difference_element_recovered";
  }
}

nlohmann::ordered_json coil_results_json(const CoilResults& results) {
  nlohmann::ordered_json coils = nlohmann::ordered_json::array();
  const auto& l = results.inductance_H;
  for (std::size_t k = 0; k < results.coils.size(); ++k) {
    const CoilResult& c = results.coils[k];
    const auto i = static_cast<Eigen::Index>(k);
    // d lambda / dI (the matrix's diagonal, null when not computed) and lambda / I, which
    // counts the magnets' and the other coils' flux (as 2D and the analytic models say).
    coils.push_back(
        {{"name", c.name},
         {"turns", c.turns},
         {"current_A", c.current_A},
         {"resistance_ohm", c.resistance_ohm},
         {"power_W", c.power_W},
         {"flux_linkage_Wb", c.flux_linkage_Wb},
         {"inductance_H", i < l.rows() ? nlohmann::ordered_json(l(i, i)) : nullptr},
         {"linkage_per_ampere_H",
          c.current_A != 0 ? nlohmann::ordered_json(c.flux_linkage_Wb / c.current_A) : nullptr},
         {"force_N", {c.force_N.x(), c.force_N.y(), c.force_N.z()}},
         {"torque_Nm", {c.torque_Nm.x(), c.torque_Nm.y(), c.torque_Nm.z()}}});
  }
  return coils;
}

void add_coil_results_json(nlohmann::ordered_json& j, const CoilResults& results) {
  j["coils"] = coil_results_json(results);
  if (results.inductance_H.size() > 0) {
    std::vector<std::string> names;
    for (const auto& c : results.coils)
      names.push_back(c.name);
    j["inductance_H"] = inductance_matrix_json(names, results.inductance_H);
  }
  j["coil_warnings"] = results.warnings;
}

std::string describe_coils(const CoilResults& results) {
  std::string s;
  char buf[320];
  for (const auto& c : results.coils) {
    std::snprintf(buf, sizeof buf,
                  "coil     %-12s %g turns x %g A: R %.4g ohm, %.4g W, linkage %.6g Wb, "
                  "F (%.4g, %.4g, %.4g) N, T (%.4g, %.4g, %.4g) N m\n",
                  c.name.c_str(), c.turns, c.current_A, c.resistance_ohm, c.power_W,
                  c.flux_linkage_Wb, c.force_N.x(), c.force_N.y(), c.force_N.z(), c.torque_Nm.x(),
                  c.torque_Nm.y(), c.torque_Nm.z());
    s += buf;
  }
  if (results.inductance_H.size() > 0 && results.inductance_H.rows() <= 4)
    s += "L = dlambda/dI (H, differential; linkage / I, the apparent one, in summary.json):\n";
  s += describe_inductance_matrix(results.inductance_H);
  for (const auto& w : results.warnings)
    s += "warning  " + w + "\n";
  return s;
}

} // namespace magfem
