#include "pipeline/adapt3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.hpp"

namespace magfem {
namespace {

// No adaptive size below this fraction of the domain radius: a field singularity (a magnet's
// edge) would otherwise ask for ever smaller tets until max_unknowns stops the loop.
constexpr double min_size_fraction = 1e-4;
// Damping of the size rule: the exponent 1 / (p + 3/2) instead of 1 / p. An element's own
// indicator falls like h^(p + 3/2) in 3D when it shrinks in a fixed field (eta_K^2 ~ h^2p
// times its volume); with 1 / p, one pass of the magnetized sphere overshot its aim (half the
// target) by 8x in the estimate at 8x the unknowns it needed (measured while the sizes
// asked for were TetGen's edges, about 0.7 of the request: Mesh3D::tet_size).
double damped_exponent(int order) {
  return 1.0 / (order + 1.5);
}

// The size each tet was asked to have (Mesh3D::tet_size), or its longest edge for a mesh
// that does not say.
std::vector<double> requested_sizes_3d(const Mesh3D& mesh) {
  if (mesh.tet_size.size() == mesh.n_tets())
    return mesh.tet_size;
  std::vector<double> h(mesh.n_tets());
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const auto& k = mesh.tets[t];
    double longest2 = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        longest2 = std::max(longest2, (mesh.nodes[k[i]] - mesh.nodes[k[j]]).squaredNorm());
    h[t] = std::sqrt(longest2);
  }
  return h;
}

} // namespace

std::vector<SizeSample3D> adapted_size_samples_3d(const Run3D& run, double target_pct,
                                                  bool coarsen) {
  const Mesh3D& mesh = run.mesh;
  // The open-boundary shell has its own indicator (error_estimate3d.hpp) and takes the same
  // rule as the physical tets: its sources go into the one size field that sizes every
  // region, the shell's surfaces and volume included (mesher3d.cpp).
  const std::vector<double> ratio = adapt_size_ratios(
      run.error_estimate.eta2_J, run.energy.total_J, run.spec.order, target_pct, coarsen,
      [](std::size_t) { return false; }, damped_exponent(run.spec.order));
  const std::vector<double> h = requested_sizes_3d(mesh);
  const double floor = min_size_fraction * run.spec.geometry3d.outer.radius;
  std::vector<double> node_h(mesh.n_nodes(), std::numeric_limits<double>::infinity());
  std::vector<SizeSample3D> out;
  out.reserve(mesh.n_tets() + mesh.n_nodes());
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const double target = std::max(floor, h[t] * ratio[t]);
    Vec3 centroid = Vec3::Zero();
    for (int v : mesh.tets[t]) {
      centroid += 0.25 * mesh.nodes[v];
      node_h[v] = std::min(node_h[v], target);
    }
    out.push_back({centroid, target});
  }
  // Corners too: a centroid source alone would leave a tet's corners up to about half an
  // element of grading above its target.
  for (std::size_t v = 0; v < mesh.n_nodes(); ++v)
    if (std::isfinite(node_h[v]))
      out.push_back({mesh.nodes[v], node_h[v]});
  return out;
}

std::unique_ptr<Run3D> run_adaptive_3d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass&)>& on_pass) {
  if (overrides.world.distributed())
    throw InputError(spec.file, spec.adapt.line, "adapt",
                     "adaptive refinement runs on one process; run this case without mpirun");
  const std::vector<AdaptQuantity> quantities = resolve_adapt_quantities(spec);
  const std::vector<std::string> b_columns = {"Bx", "By", "Bz"};
  std::shared_ptr<const std::vector<SizeSample3D>> sizes;
  const auto with_sizes = [&] {
    CaseSpec s = spec;
    s.geometry3d.options.refine_sizes = sizes;
    return s;
  };
  std::unique_ptr<Run3D> run;
  AdaptSteps steps;
  steps.dimension = 3;
  steps.order = overrides.order > 0 ? overrides.order : spec.order;
  steps.solve = [&](int) {
    run.reset(); // the previous pass's memory is free before the next one meshes
    run = run_case_3d(with_sizes(), overrides);
    AdaptMeasure m{run->mesh.n_tets(),
                   run->dofs->n_dofs(),
                   run->energy.total_J,
                   run->error_estimate.energy_error_pct,
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
    sizes = std::make_shared<const std::vector<SizeSample3D>>(
        adapted_size_samples_3d(*run, target_pct, coarsen));
    // The mesher's own estimate of the next mesh (the case's sizes and the new sources), and
    // the memory guard on it: a pass that would not fit ends the loop, not the run.
    try {
      const MeshEstimate3D next = check_memory_3d(with_sizes(), overrides);
      const double per_tet = double(run->dofs->n_dofs()) / double(run->mesh.n_tets());
      return AdaptPlan{next.tetrahedra * per_tet, ""};
    } catch (const InputError& e) {
      return AdaptPlan{0, std::string("memory guard: ") + e.what()};
    }
  };
  file_adapt_history(*run, run_adapt_loop(spec.adapt, steps, on_pass));
  return run;
}

} // namespace magfem
