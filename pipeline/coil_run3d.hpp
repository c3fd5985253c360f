#pragma once
// The coil part of the 3D pipeline: the coils' source field for the solver, the check that
// coils lie in air, and the per-coil results (resistance, loss, flux linkage, Lorentz force
// and torque, inductance matrix) for summary.json and forces.csv.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "mesh/coil3d.hpp"
#include "pipeline/force_results.hpp"
#include "solver/source_field3d.hpp"
#include "solver/source_field_cache3d.hpp"
#include "sources/coil_field_options.hpp"

namespace magfem {

class PatchRecovery3D;

class CoilField;
struct Run3D;
class Assembler3D;

// Accuracy of the source field as the FE stages use it. The library's default (1e-8) serves
// the sources' own tests and the analytic command; the FE field's discretisation error is
// 1e-3 or more, so ~2e-4 near the bundles is invisible in FE results, and for racetracks it
// is 10 times faster (TEAM 20 coil: ~30 instead of ~290 us per point).
CoilFieldOptions fe_source_options();

// The most memory (MB) the memo of the coils' source field may take in a run.
inline constexpr double coil_field_cache_limit_mb = 1300;

// SourceField3D over the case's coils (sources/coil_field.hpp), memoised at points.
class CaseCoils : public SourceField3D {
public:
  explicit CaseCoils(const std::vector<Coil3D>& coils, const CoilFieldOptions& options = {});
  ~CaseCoils() override;
  int n_coils() const override { return static_cast<int>(fields_.size()); }
  double current(int coil) const override { return coils_[coil].current; }
  double turns(int coil) const override { return coils_[coil].turns; }
  Eigen::Vector3d H(const Eigen::Vector3d& x) const override;
  Eigen::Vector3d H_per_ampere(int coil, const Eigen::Vector3d& x) const override;
  void H_per_ampere_all(const Eigen::Vector3d& x, Eigen::Vector3d* out) const override;
  void H_per_ampere_all_once(const Eigen::Vector3d& x, Eigen::Vector3d* out) const override;
  Eigen::Vector3d J(const Eigen::Vector3d& x) const override;
  const CoilField& field(int coil) const { return *fields_[coil]; }
  const Coil3D& coil(int k) const { return coils_[k]; }

private:
  std::vector<Coil3D> coils_;
  std::vector<std::unique_ptr<CoilField>> fields_;
  SourceFieldCache3D cache_; // H per ampere of every coil at the points already asked for
};

struct CoilResult {
  std::string name;
  double turns = 0, current_A = 0, resistance_ohm = 0, power_W = 0, flux_linkage_Wb = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_Nm = Eigen::Vector3d::Zero(); // about the origin
};

struct CoilResults {
  std::vector<CoilResult> coils;
  Eigen::MatrixXd inductance_H; // empty if not computed
  // Seconds for the inductance matrix: the tangent, its preconditioner set-up, the block solve
  // of all coils' sensitivities and the integrals (part of the post-processing time).
  double inductance_s = 0;
  std::vector<std::string> warnings;
};

// Exit-2 error (InputError naming the coil's line and the part) if a coil overlaps a magnet
// or iron part or leaves the domain ball. From the geometry alone, before meshing: the coil's
// volume quadrature points are tested against the exact parts, so a slip is reported in
// milliseconds rather than after a mesh that can take minutes.
void check_coils_in_air(const CaseSpec& spec, const CaseCoils& coils);
// The linear solver options of the coils' sensitivity solves (the case's, at most 1e-5 tight:
// the inductance takes the variational correction, coil_run3d.cpp).
LinearSolverOptions sensitivity_solver_options(LinearSolverOptions options);
// The same for the distributed solves under mpirun (a decade tighter: coil_run3d.cpp).
LinearSolverOptions distributed_sensitivity_solver_options(LinearSolverOptions options);
// u: the converged free-DOF solution. The sensitivities are run.coil_sensitivities when a
// distributed solve computed them, else solved here.
CoilResults compute_coil_results(const Run3D& run, const Assembler3D& assembler,
                                 const Eigen::VectorXd& u);
// Lorentz force specs of the case (sums over the named coils) as force results.
std::vector<ForceResult> coil_lorentz_forces(const Run3D& run);
// Each Lorentz force result's one-mesh error estimate (force_err, torque_err): per
// component, the difference between the reported integral of the element field and the same
// integral of the patch-recovered field (coil_run3d.cpp says why). `forces` holds the
// results by name, as coil_lorentz_forces made them.
void estimate_lorentz_errors_3d(const Run3D& run, const PatchRecovery3D& recovery,
                                std::vector<ForceResult>& forces);
nlohmann::ordered_json coil_results_json(const CoilResults& results);
// summary.json's coils (coil_results_json), inductance_H {names, matrix} when computed, and
// coil_warnings.
void add_coil_results_json(nlohmann::ordered_json& j, const CoilResults& results);
std::string describe_coils(const CoilResults& results);

} // namespace magfem
