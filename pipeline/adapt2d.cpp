#include "pipeline/adapt2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "core/input_error.hpp"
#include "mesh/adaptive_size2d.hpp"

namespace magfem {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// Refinement and coarsening limits per pass: beyond them the indicator of the old mesh says
// little about the new one.
constexpr double min_ratio = 0.3, max_ratio = 2.0;
// The next pass aims at half the target: a pass that lands just above it would cost one more.
constexpr double aim_below_target = 0.5;
// Once the energy is within the target but a named quantity is not, each pass asks for this
// fraction of the energy error reached, so that the mesh keeps getting finer.
constexpr double quantity_push = 0.25;
// Bounds of the observed ratio of successive changes used to extrapolate a quantity's error:
// below 0.25 the ratio of two noisy changes on non-nested meshes is not trusted (the estimate
// stays at least a third of the last change), at 1 the sequence is not converging (9x).
constexpr double min_change_ratio = 0.25, max_change_ratio = 0.9;

double length_factor(const CaseSpec& spec) {
  return spec.stack_length > 0 ? spec.stack_length : 1.0;
}

double force_component(const ForceResult& f, const std::string& c) {
  if (c == "force")
    return f.force.norm();
  if (c == "torque")
    return f.torque.norm();
  const Eigen::Vector3d& v = c[0] == 'F' ? f.force : f.torque;
  return v[c[1] - 'x'];
}

// rms |B| over a probe's samples (planar Bx, By or axisymmetric Br, Bz columns).
double probe_rms_b(const ProbeTable& t, bool axi) {
  const std::size_t i = t.column(axi ? "Br" : "Bx"), j = t.column(axi ? "Bz" : "By");
  double sum = 0;
  for (const auto& row : t.rows)
    sum += row[i] * row[i] + row[j] * row[j];
  return t.rows.empty() ? 0.0 : std::sqrt(sum / double(t.rows.size()));
}

double quantity_value(const Run2D& run, const AdaptQuantity& q) {
  switch (q.kind) {
  case AdaptQuantity::Kind::energy:
    return run.energy.total_J_per_m * length_factor(run.spec);
  case AdaptQuantity::Kind::force:
    for (const auto& f : run.forces)
      if (f.name == q.name)
        return force_component(f, q.component);
    break;
  case AdaptQuantity::Kind::probe:
    for (const auto& p : run.probes)
      if (p.name == q.name)
        return probe_rms_b(p, run.spec.axisymmetric());
    break;
  }
  return nan; // not reached: the reader checked the names
}

// The estimated relative error (%) of quantity i at the last pass: its last change, times
// rho / (1 - rho) for the observed ratio rho of the last two changes (the geometric tail of
// the changes still to come). Unknown (NaN) on the first pass.
double extrapolated_error_pct(const std::vector<AdaptPass2D>& passes, std::size_t i) {
  const std::size_t n = passes.size();
  if (n < 2)
    return nan;
  const auto value = [&](std::size_t k) { return passes[k].quantities[i].second; };
  const double change = std::abs(value(n - 1) - value(n - 2));
  double factor = 1.0; // two passes: the last change itself (rho = 1/2)
  if (n >= 3) {
    const double before = std::abs(value(n - 2) - value(n - 3));
    const double rho = before > 0 ? std::clamp(change / before, min_change_ratio, max_change_ratio)
                                  : max_change_ratio;
    factor = rho / (1 - rho);
  }
  const double scale = std::abs(value(n - 1));
  return scale > 0 ? 100 * change * factor / scale : std::numeric_limits<double>::infinity();
}

AdaptPass2D record_pass(const Run2D& run, int pass, const std::vector<AdaptQuantity>& quantities,
                        const std::vector<std::string>& names, std::vector<AdaptPass2D>& passes) {
  AdaptPass2D p;
  p.pass = pass;
  p.elements = run.mesh.n_triangles();
  p.unknowns = run.dofs->n_dofs();
  p.energy_J = run.energy.total_J_per_m * length_factor(run.spec);
  p.energy_error_pct = run.error.energy_error_pct;
  p.delta_energy_pct =
      passes.empty() ? nan : 100 * std::abs(p.energy_J - passes.back().energy_J) / p.energy_J;
  for (std::size_t i = 0; i < quantities.size(); ++i)
    p.quantities.emplace_back(names[i], quantity_value(run, quantities[i]));
  passes.push_back(p);
  for (std::size_t i = 0; i < quantities.size(); ++i)
    passes.back().quantity_error_pct.push_back(quantities[i].kind == AdaptQuantity::Kind::energy
                                                   ? p.energy_error_pct
                                                   : extrapolated_error_pct(passes, i));
  return passes.back();
}

bool reached(const AdaptPass2D& p, double accuracy_pct) {
  if (!(p.energy_error_pct <= accuracy_pct))
    return false;
  return std::all_of(p.quantity_error_pct.begin(), p.quantity_error_pct.end(),
                     [&](double e) { return e <= accuracy_pct; }); // NaN: not yet
}

std::vector<AdaptQuantity> resolve(const CaseSpec& spec) {
  std::vector<AdaptQuantity> out;
  for (const auto& name : spec.adapt.quantities) {
    std::string why;
    const auto q = parse_adapt_quantity(name, spec, why);
    if (!q)
      throw InputError(spec.file, spec.adapt.line, "adapt.quantities", why);
    out.push_back(*q);
  }
  return out;
}

double mesher_floor(const MeshOptions2D& o) {
  return std::min(1.0, o.size_scale) * o.chord_tolerance / o.gap_layers; // as mesher2d.cpp
}

} // namespace

std::vector<double> adapted_sizes(const Run2D& run, double target_pct, bool coarsen) {
  const std::vector<double> h = longest_edges(run.mesh);
  const std::size_t n = h.size();
  // The total eta^2 that target_pct allows (energy_error_pct = 100 eta^2 / (2 W)), shared
  // equally by the elements.
  const double allowed = 2 * run.energy.total_J_per_m * target_pct / 100;
  const double eta_target = std::sqrt(allowed / double(n));
  const int p = run.spec.order;
  std::vector<double> out(n);
  for (std::size_t t = 0; t < n; ++t) {
    const double eta = std::sqrt(std::max(run.error.eta2[t], 0.0));
    double ratio = eta > 0 ? std::pow(eta_target / eta, 1.0 / p) : max_ratio;
    ratio = std::clamp(ratio, min_ratio, max_ratio);
    if (!coarsen || run.problem.is_shell(t))
      ratio = std::min(ratio, 1.0);
    out[t] = h[t] * ratio;
  }
  return out;
}

std::unique_ptr<Run2D> run_adaptive_2d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass2D&)>& on_pass) {
  const AdaptSpec& a = spec.adapt;
  const std::vector<AdaptQuantity> quantities = resolve(spec);
  AdaptHistory2D history{a.accuracy_pct, false, "", {}};
  std::optional<SizeField2D> sizes;
  std::unique_ptr<Run2D> run;
  for (int pass = 1;; ++pass) {
    const auto t0 = Clock::now();
    RunOverrides ov = overrides;
    ov.refine_sizes = sizes ? &*sizes : nullptr;
    run = run_case_2d(spec, ov);
    const AdaptPass2D& p = record_pass(*run, pass, quantities, a.quantities, history.passes);
    if (reached(p, a.accuracy_pct)) {
      history.converged = true;
    } else if (pass >= a.max_passes) {
      history.stop_reason = "max_passes (" + std::to_string(a.max_passes) + ") reached";
    } else {
      // Energy within the target, a quantity not: refine further and coarsen nowhere, so that
      // the quantity's sequence of passes converges instead of trading one region for another.
      const bool energy_reached = p.energy_error_pct <= a.accuracy_pct;
      const double target =
          energy_reached ? quantity_push * p.energy_error_pct : aim_below_target * a.accuracy_pct;
      const std::vector<double> next = adapted_sizes(*run, target, !energy_reached);
      const std::vector<double> h = longest_edges(run->mesh);
      double growth = 0; // the element count scales like the inverse square of the size
      for (std::size_t t = 0; t < h.size(); ++t)
        growth += (h[t] / next[t]) * (h[t] / next[t]);
      const double predicted = p.unknowns * growth / double(h.size());
      if (predicted > a.max_unknowns) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "max_unknowns (%.3g) reached: the next pass needs ~%.3g",
                      a.max_unknowns, predicted);
        history.stop_reason = buf;
      } else {
        sizes.emplace(adaptive_size_field(run->mesh, next, mesher_floor(spec.geometry2d.options)));
      }
    }
    history.passes.back().seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (on_pass)
      on_pass(history.passes.back());
    if (history.converged || !history.stop_reason.empty())
      break;
  }
  if (!history.converged) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "adaptive refinement stopped before reaching %.3g %%: %s; estimated energy "
                  "error %.3g %%",
                  a.accuracy_pct, history.stop_reason.c_str(),
                  history.passes.back().energy_error_pct);
    run->warnings.push_back(buf);
  }
  run->adapt = std::move(history);
  return run;
}

std::string describe_adapt_pass(const AdaptPass2D& p) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "pass %-3d %zu triangles, %d unknowns, energy %.7g, error %.3g %%",
                p.pass, p.elements, p.unknowns, p.energy_J, p.energy_error_pct);
  std::string s = buf;
  if (std::isfinite(p.delta_energy_pct)) {
    std::snprintf(buf, sizeof buf, ", change %.3g %%", p.delta_energy_pct);
    s += buf;
  }
  for (std::size_t i = 0; i < p.quantities.size(); ++i) {
    if (p.quantities[i].first == "energy")
      continue;
    std::snprintf(buf, sizeof buf, ", %s %.7g", p.quantities[i].first.c_str(),
                  p.quantities[i].second);
    s += buf;
    if (std::isfinite(p.quantity_error_pct[i]))
      std::snprintf(buf, sizeof buf, " (error %.3g %%)", p.quantity_error_pct[i]);
    else
      std::snprintf(buf, sizeof buf, " (error unknown yet)");
    s += buf;
  }
  std::snprintf(buf, sizeof buf, ", %.2f s\n", p.seconds);
  return s + buf;
}

} // namespace magfem
