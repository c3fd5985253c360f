#pragma once
// The adaptive loop shared by 2D/axisymmetric (adapt2d.hpp) and 3D (adapt3d.hpp) solves:
//   solve a pass -> record it -> stop when the estimated energy error and the estimated error
//   of every named quantity are below accuracy_pct, or at a limit -> else plan the next mesh.
// The dimensions differ only in how a pass is solved and how the next mesh is asked for (a
// CGAL size field in 2D, size sources for TetGen in 3D); the marking rule (adapt_size_ratios),
// the quantities' error estimate and the stopping rule are the same, and live here.
//
// The error of a named quantity (force, torque, probe) is its change between the last two
// passes, extrapolated to the limit with the order the last three passes show, bounded to
// what the elements can show (extrapolated_error_pct); the energy's is the estimator's. Reaching
// max_passes, max_unknowns or the memory guard first stops with converged = false, a stop reason
// and a warning: never a silent pass.
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_spec.hpp"
#include "pipeline/force_results.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

// The next pass aims at this fraction of the target: a pass that lands just above it would
// cost one more. Shared by the energy rule (adapt_loop.cpp) and the 3D probe rule (adapt3d.cpp).
inline constexpr double aim_below_target = 0.5;

// One pass of an adaptive solve, as summary.json's adapt.passes[] reports it.
struct AdaptPass {
  int pass = 0;
  std::size_t elements = 0;
  int unknowns = 0;
  double energy_J = 0;         // as summary.json energy_J (2D: per metre, stack or revolution)
  double energy_error_pct = 0; // the estimator's (error_estimate2d.hpp, error_estimate3d.hpp)
  double delta_energy_pct = 0; // |W - W_previous| / W; NaN on the first pass
  std::vector<std::pair<std::string, double>> quantities; // the named quantities' values
  std::vector<double> quantity_error_pct; // their estimated relative errors (NaN: unknown yet)
  double seconds = 0;
};

struct AdaptHistory {
  double accuracy_pct = 0;
  bool converged = false;
  std::string stop_reason; // why it stopped without converging (empty when converged)
  std::vector<AdaptPass> passes;
};

// What one solved pass tells the loop.
struct AdaptMeasure {
  std::size_t elements = 0;
  int unknowns = 0;
  double energy_J = 0;
  double energy_error_pct = 0;
  std::vector<double> quantities; // parallel to the resolved quantities
  // Their relative errors (%) estimated from this mesh alone where the result has one (the 3D
  // stress tensor's force estimate), else NaN: a floor under the estimate from the passes.
  std::vector<double> quantity_mesh_error_pct;
  // Per quantity (empty: none): its one-mesh estimate bounds its error from above, and is
  // then its estimate alone. A 3D probe table's: the element field's local error, where the
  // table holds the patch recovery, one order better (probes3d.hpp). The change from a
  // coarser pass is that pass's error, not this one's: as a floor it had the loop refine a
  // mesh whose table it had already met (the sphere's r = 12 mm table at 0.1 %: 0.031 % true
  // after pass 2, a change-floored 1.37 % estimate and a third pass of 2.2 M unknowns).
  std::vector<bool> quantity_mesh_error_bounds;
};

// The next mesh as planned: its predicted unknowns, or why it cannot be made (the memory
// guard's message); the loop stops on either limit.
struct AdaptPlan {
  double predicted_unknowns = 0;
  std::string refusal; // non-empty: stop with this reason
};

// The dimension's side of the loop. solve(pass): mesh (the case's sizes on pass 1, else the
// last accepted plan's), solve, estimate and measure. plan(target_pct, coarsen): the sizes
// for the next pass from the last solve's indicators (adapt_size_ratios), kept until the
// next solve.
struct AdaptSteps {
  std::function<AdaptMeasure(int pass)> solve;
  std::function<AdaptPlan(double target_pct, bool coarsen)> plan;
  int dimension = 2; // of the mesh: its size h ~ elements^(-1/dimension)
  int order = 2;     // of the elements: bounds the order a quantity's changes may show
};

// The estimated relative error (%) of the last of a quantity's values on successively refined
// meshes (`elements` per pass; NaN for one value, the last change for two). From three on,
// Richardson extrapolation with the order p at which an error C h^p gives the last two
// changes, p bounded to [1, 2 order] (a ratio of changes beyond it is noise or
// pre-asymptotic, not a rate). Where the order cannot be observed (changes of opposite signs:
// the values bracket their limit; a zero change; a pass that hardly refined) it is the last
// change itself.
double extrapolated_error_pct(const std::vector<double>& values,
                              const std::vector<double>& elements, int dimension, int order);

// The quantities spec.adapt names, resolved (InputError at adapt.quantities otherwise).
std::vector<AdaptQuantity> resolve_adapt_quantities(const CaseSpec& spec);

// The value of a named quantity: energy_J, a force component, or a probe's rms |B| over the
// `b_columns` of its table (planar Bx By, axisymmetric Br Bz, 3D Bx By Bz).
double adapt_quantity_value(const AdaptQuantity& q, double energy_J,
                            const std::vector<ForceResult>& forces,
                            const std::vector<ProbeTable>& probes,
                            const std::vector<std::string>& b_columns);

// A force quantity's relative error (%) as the force's own one-mesh estimate gives it
// (ForceResult::force_err, torque_err: 3D stress tensor and Lorentz), or NaN (energy, probes,
// a force without an estimate).
double adapt_quantity_mesh_error_pct(const AdaptQuantity& q,
                                     const std::vector<ForceResult>& forces);

// Runs the loop to convergence or a limit; on_pass (may be empty) hears every pass as it
// ends. The caller's last solve is the last pass.
AdaptHistory run_adapt_loop(const AdaptSpec& spec, const AdaptSteps& steps,
                            const std::function<void(const AdaptPass&)>& on_pass);

// The refinement ratio h_new / h of every element from its indicator eta_K^2 (J, or J/m in
// 2D): elements whose indicator exceeds the equidistributed share of the target shrink, the
// others grow,
//   h_new = h * clamp((eta_target / eta_K)^(1/p), 0.3, 2)    (p: the element order),
// the rule of Zienkiewicz and Zhu (1987): eta_K scales like h^p in the energy norm when the
// number of elements is held fixed. target_pct: the energy error aimed at (energy_error_pct's
// measure, 100 sum eta^2 / (2 W)), shared equally by all elements. Elements `in_shell` never
// grow (2D: they keep the layers the mesher gives the open boundary; 3D passes none: its
// shell follows its own indicator). coarsen = false: no ratio above 1. `exponent` replaces 1/p when
// positive (the damping of 3D, adapt3d.cpp).
std::vector<double> adapt_size_ratios(const std::vector<double>& eta2, double energy, int order,
                                      double target_pct, bool coarsen,
                                      const std::function<bool(std::size_t)>& in_shell,
                                      double exponent = 0);

// The warning of a loop that stopped before its target ("" when it converged).
std::string adapt_warning(const AdaptHistory& h);

// Files the history in the last pass's run (Run2D or Run3D), with the warning when the loop
// stopped before its target.
template <class Run> void file_adapt_history(Run& run, AdaptHistory history) {
  if (!history.converged)
    run.warnings.push_back(adapt_warning(history));
  run.adapt = std::move(history);
}

// summary.json's adapt block.
nlohmann::ordered_json adapt_json(const AdaptHistory& h);
// An estimate as JSON: NaN (not known) as null, which JSON has for it.
template <class Json = nlohmann::ordered_json> Json number_or_null(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

// One console line for a pass; `element_word`: "triangles" or "tetrahedra".
std::string describe_adapt_pass(const AdaptPass& pass, const char* element_word = "triangles");

// The summary's line: reached or not, after how many passes.
std::string describe_adapt_result(const AdaptHistory& h);

} // namespace magfem
