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
// target) by 8x in the estimate at 8x the unknowns it needed.
double damped_exponent(int order) {
  return 1.0 / (order + 1.5);
}

std::vector<double> longest_edges_3d(const Mesh3D& mesh) {
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
  const auto in_shell = [&](std::size_t t) { return run.problem.is_shell(t); };
  const std::vector<double> ratio =
      adapt_size_ratios(run.error_estimate.eta2_J, run.energy.total_J, run.spec.order, target_pct,
                        coarsen, in_shell, damped_exponent(run.spec.order));
  const std::vector<double> h = longest_edges_3d(mesh);
  const double floor = min_size_fraction * run.spec.geometry3d.outer.radius;
  // The shell's size: no coarser than the geometric mean target of the physical tets with a
  // node on it. Its error is not estimated but is not small: on the coarse sphere of
  // tests/pipeline/test_adapt3d.cpp a 4x finer shell alone halves the true energy error.
  std::vector<char> on_shell(mesh.n_nodes(), 0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (in_shell(t))
      for (int v : mesh.tets[t])
        on_shell[v] = 1;
  double log_sum = 0;
  std::size_t n_touching = 0;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (!in_shell(t) && std::any_of(mesh.tets[t].begin(), mesh.tets[t].end(),
                                    [&](int v) { return on_shell[v] != 0; })) {
      log_sum += std::log(h[t] * ratio[t]);
      ++n_touching;
    }
  const double shell_h =
      n_touching ? std::exp(log_sum / double(n_touching)) : std::numeric_limits<double>::infinity();
  std::vector<double> node_h(mesh.n_nodes(), std::numeric_limits<double>::infinity());
  std::vector<SizeSample3D> out;
  out.reserve(mesh.n_tets() + mesh.n_nodes());
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const double target = std::max(floor, in_shell(t) ? std::min(h[t], shell_h) : h[t] * ratio[t]);
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
  steps.solve = [&](int) {
    run.reset(); // the previous pass's memory is free before the next one meshes
    run = run_case_3d(with_sizes(), overrides);
    AdaptMeasure m{run->mesh.n_tets(),
                   run->dofs->n_dofs(),
                   run->energy.total_J,
                   run->error_estimate.energy_error_pct,
                   {}};
    for (const auto& q : quantities)
      m.quantities.push_back(
          adapt_quantity_value(q, m.energy_J, run->forces, run->probes, b_columns));
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
