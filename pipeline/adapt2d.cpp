#include "pipeline/adapt2d.hpp"

#include <optional>

#include "mesh/adaptive_size2d.hpp"

namespace magfem {
namespace {

double length_factor(const CaseSpec& spec) {
  return spec.stack_length > 0 ? spec.stack_length : 1.0;
}

double mesher_floor(const MeshOptions2D& o) {
  return std::min(1.0, o.size_scale) * o.chord_tolerance / o.gap_layers; // as mesher2d.cpp
}

} // namespace

std::vector<double> adapted_sizes(const Run2D& run, double target_pct, bool coarsen) {
  std::vector<double> h = longest_edges(run.mesh);
  const std::vector<double> ratio = adapt_size_ratios(
      run.error_estimate.eta2, run.energy.total_J_per_m, run.spec.order, target_pct, coarsen,
      [&](std::size_t t) { return run.problem.is_shell(t); });
  for (std::size_t t = 0; t < h.size(); ++t)
    h[t] *= ratio[t];
  return h;
}

std::unique_ptr<Run2D> run_adaptive_2d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass&)>& on_pass) {
  const std::vector<AdaptQuantity> quantities = resolve_adapt_quantities(spec);
  const std::vector<std::string> b_columns = spec.axisymmetric()
                                                 ? std::vector<std::string>{"Br", "Bz"}
                                                 : std::vector<std::string>{"Bx", "By"};
  std::optional<SizeField2D> sizes;
  std::unique_ptr<Run2D> run;
  AdaptSteps steps;
  steps.dimension = 2;
  steps.order = overrides.order > 0 ? overrides.order : spec.order;
  steps.solve = [&](int) {
    RunOverrides ov = overrides;
    ov.refine_sizes = sizes ? &*sizes : nullptr;
    run = run_case_2d(spec, ov);
    AdaptMeasure m{run->mesh.n_triangles(),
                   run->dofs->n_dofs(),
                   run->energy.total_J_per_m * length_factor(run->spec),
                   run->error_estimate.energy_error_pct,
                   {},
                   {},
                   {}};
    for (const auto& q : quantities) {
      m.quantities.push_back(
          adapt_quantity_value(q, m.energy_J, run->forces, run->probes, b_columns));
      m.quantity_mesh_error_pct.push_back(adapt_quantity_mesh_error_pct(q, run->forces));
    }
    return m;
  };
  steps.plan = [&](double target_pct, bool coarsen) {
    const std::vector<double> next = adapted_sizes(*run, target_pct, coarsen);
    const std::vector<double> h = longest_edges(run->mesh);
    double growth = 0; // the element count scales like the inverse square of the size
    for (std::size_t t = 0; t < h.size(); ++t)
      growth += (h[t] / next[t]) * (h[t] / next[t]);
    sizes.emplace(adaptive_size_field(run->mesh, next, mesher_floor(spec.geometry2d.options)));
    return AdaptPlan{run->dofs->n_dofs() * growth / double(h.size()), ""};
  };
  file_adapt_history(*run, run_adapt_loop(spec.adapt, steps, on_pass));
  return run;
}

} // namespace magfem
