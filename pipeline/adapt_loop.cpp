#include "pipeline/adapt_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/input_error.hpp"

namespace magfem {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// Refinement and coarsening limits per pass: beyond them the indicator of the old mesh says
// little about the new one.
constexpr double min_ratio = 0.3, max_ratio = 2.0;
// Once the energy is within the target but a named quantity is not, each pass asks for this
// fraction of the energy error reached, so that the mesh keeps getting finer.
constexpr double quantity_push = 0.25;
// A refinement that shrinks the mesh size by less than 10 % (fewer than 1.21x the triangles,
// 1.33x the tetrahedra) says little about the order: its change is mostly the noise of a new,
// non-nested mesh, and extrapolating it at order 1 would multiply it by more than 10.
constexpr double min_size_ratio = 1.1;

double force_component(const ForceResult& f, const std::string& c) {
  if (c == "force")
    return f.force.norm();
  if (c == "torque")
    return f.torque.norm();
  const Eigen::Vector3d& v = c[0] == 'F' ? f.force : f.torque;
  return v[c[1] - 'x'];
}

double probe_rms_b(const ProbeTable& t, const std::vector<std::string>& b_columns) {
  std::vector<std::size_t> cols;
  for (const auto& c : b_columns)
    cols.push_back(t.column(c));
  double sum = 0;
  for (const auto& row : t.rows)
    for (std::size_t i : cols)
      sum += row[i] * row[i];
  return t.rows.empty() ? 0.0 : std::sqrt(sum / double(t.rows.size()));
}

// f(p) = d_before / d_last for an error C h^p on meshes whose sizes shrink by r1, then r2
// (h1 = r1 h2, h2 = r2 h3): r2^p (r1^p - 1) / (r2^p - 1), increasing in p.
double change_ratio_at_order(double p, double r1, double r2) {
  return std::pow(r2, p) * (std::pow(r1, p) - 1) / (std::pow(r2, p) - 1);
}

// The order p in [p_min, p_max] at which change_ratio_at_order equals `ratio` (bisection;
// the bound when the ratio lies beyond it).
double bounded_order(double ratio, double r1, double r2, double p_min, double p_max) {
  if (ratio <= change_ratio_at_order(p_min, r1, r2))
    return p_min;
  if (ratio >= change_ratio_at_order(p_max, r1, r2))
    return p_max;
  double lo = p_min, hi = p_max;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (change_ratio_at_order(mid, r1, r2) < ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The estimated relative error (%) of quantity i at the last pass. Unknown (NaN) on the first
// pass; the last change on the second.
double quantity_error_pct(const std::vector<AdaptPass>& passes, std::size_t i, int dimension,
                          int order) {
  const std::size_t n = passes.size();
  if (n < 2)
    return nan;
  std::vector<double> values, elements;
  for (const auto& p : passes)
    values.push_back(p.quantities[i].second), elements.push_back(double(p.elements));
  return extrapolated_error_pct(values, elements, dimension, order);
}

const AdaptPass& record_pass(const AdaptMeasure& m, int pass, const AdaptSpec& spec,
                             const AdaptSteps& steps, std::vector<AdaptPass>& passes) {
  AdaptPass p;
  p.pass = pass;
  p.elements = m.elements;
  p.unknowns = m.unknowns;
  p.energy_J = m.energy_J;
  p.energy_error_pct = m.energy_error_pct;
  p.delta_energy_pct =
      passes.empty() ? nan : 100 * std::abs(p.energy_J - passes.back().energy_J) / p.energy_J;
  for (std::size_t i = 0; i < m.quantities.size(); ++i)
    p.quantities.emplace_back(spec.quantities[i], m.quantities[i]);
  passes.push_back(p);
  for (std::size_t i = 0; i < m.quantities.size(); ++i) {
    double e = spec.quantities[i] == "energy"
                   ? p.energy_error_pct
                   : quantity_error_pct(passes, i, steps.dimension, steps.order);
    // The change between passes cannot see an error every pass shares: two spheres' force
    // changed by 0.01 % between the last passes while it was 0.19 % off the exact one, which
    // the stress tensor's own estimate (0.19-0.24 %) did see; and a change can be small by
    // chance (the small actuator's Lorentz torque: 0.026 % between two passes, 0.14 % off the
    // exact). The larger of the two, from the second pass on (the first has no change to
    // compare and stays unknown).
    const double mesh = i < m.quantity_mesh_error_pct.size() ? m.quantity_mesh_error_pct[i] : nan;
    const bool bound = i < m.quantity_mesh_error_bounds.size() && m.quantity_mesh_error_bounds[i];
    if (std::isfinite(e) && std::isfinite(mesh))
      e = bound ? mesh : std::max(e, mesh);
    passes.back().quantity_error_pct.push_back(e);
  }
  return passes.back();
}

bool reached(const AdaptPass& p, double accuracy_pct) {
  if (!(p.energy_error_pct <= accuracy_pct))
    return false;
  return std::all_of(p.quantity_error_pct.begin(), p.quantity_error_pct.end(),
                     [&](double e) { return e <= accuracy_pct; }); // NaN: not yet
}

} // namespace

double extrapolated_error_pct(const std::vector<double>& values,
                              const std::vector<double>& elements, int dimension, int order) {
  const std::size_t n = values.size();
  if (n < 2)
    return nan;
  const double last = values[n - 1];
  const double d2 = last - values[n - 2];
  const double scale = std::abs(last);
  if (!(scale > 0))
    return std::numeric_limits<double>::infinity();
  const double last_change_pct = 100 * std::abs(d2) / scale;
  if (n < 3 || d2 == 0)
    return last_change_pct;
  const double d1 = values[n - 2] - values[n - 3];
  // The mesh size h ~ (elements)^(-1/D) of each pass, as ratios of successive passes.
  const double r1 = std::pow(elements[n - 2] / elements[n - 3], 1.0 / dimension);
  const double r2 = std::pow(elements[n - 1] / elements[n - 2], 1.0 / dimension);
  // Changes of opposite signs (the values bracket their limit: the last value is within its
  // change of it), a first change of zero or meshes that hardly refined: no order to observe.
  if (d1 == 0 || (d1 > 0) != (d2 > 0) || !(r1 >= min_size_ratio) || !(r2 >= min_size_ratio))
    return last_change_pct;
  // The order at which the error C h^p makes the two changes, bounded to what the elements
  // can show: 1 (below it two changes are pre-asymptotic or the noise of non-nested meshes,
  // not a rate: near-equal changes extrapolated at their own ratio made an estimate of 13 %
  // for a true 0.05 %) to 2 order (an output of the field converges at most like the square
  // of its energy-norm error, h^order). Then Richardson: the error left in the last value.
  const double p = bounded_order(std::abs(d1 / d2), r1, r2, 1.0, 2.0 * order);
  return last_change_pct / (std::pow(r2, p) - 1);
}

std::vector<AdaptQuantity> resolve_adapt_quantities(const CaseSpec& spec) {
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

double adapt_quantity_value(const AdaptQuantity& q, double energy_J,
                            const std::vector<ForceResult>& forces,
                            const std::vector<ProbeTable>& probes,
                            const std::vector<std::string>& b_columns) {
  switch (q.kind) {
  case AdaptQuantity::Kind::energy:
    return energy_J;
  case AdaptQuantity::Kind::force:
    for (const auto& f : forces)
      if (f.name == q.name)
        return force_component(f, q.component);
    break;
  case AdaptQuantity::Kind::probe:
    for (const auto& p : probes)
      if (p.name == q.name)
        return probe_rms_b(p, b_columns);
    break;
  }
  return nan; // not reached: the reader checked the names
}

double adapt_quantity_mesh_error_pct(const AdaptQuantity& q,
                                     const std::vector<ForceResult>& forces) {
  if (q.kind != AdaptQuantity::Kind::force)
    return nan;
  for (const auto& f : forces) {
    if (f.name != q.name || !f.estimated)
      continue;
    const double value = std::abs(force_component(f, q.component));
    double error = 0;
    if (q.component == "force")
      error = f.force_err.norm();
    else if (q.component == "torque")
      error = f.torque_err.norm();
    else
      error = (q.component[0] == 'F' ? f.force_err : f.torque_err)[q.component[1] - 'x'];
    return value > 0 ? 100 * error / value : nan;
  }
  return nan;
}

std::vector<double> adapt_size_ratios(const std::vector<double>& eta2, double energy, int order,
                                      double target_pct, bool coarsen,
                                      const std::function<bool(std::size_t)>& in_shell,
                                      double exponent) {
  const std::size_t n = eta2.size();
  // The total eta^2 that target_pct allows (energy_error_pct = 100 eta^2 / (2 W)), shared
  // equally by the elements.
  const double allowed = 2 * energy * target_pct / 100;
  const double eta_target = std::sqrt(allowed / double(n));
  const double power = exponent > 0 ? exponent : 1.0 / order;
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double eta = std::sqrt(std::max(eta2[k], 0.0));
    double ratio = eta > 0 ? std::pow(eta_target / eta, power) : max_ratio;
    ratio = std::clamp(ratio, min_ratio, max_ratio);
    if (!coarsen || in_shell(k))
      ratio = std::min(ratio, 1.0);
    out[k] = ratio;
  }
  return out;
}

AdaptHistory run_adapt_loop(const AdaptSpec& a, const AdaptSteps& steps,
                            const std::function<void(const AdaptPass&)>& on_pass) {
  AdaptHistory history{a.accuracy_pct, false, "", {}};
  for (int pass = 1;; ++pass) {
    const auto t0 = Clock::now();
    const AdaptPass& p = record_pass(steps.solve(pass), pass, a, steps, history.passes);
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
      const AdaptPlan plan = steps.plan(target, !energy_reached);
      if (!plan.refusal.empty()) {
        history.stop_reason = plan.refusal;
      } else if (plan.predicted_unknowns > a.max_unknowns) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "max_unknowns (%.3g) reached: the next pass needs ~%.3g",
                      a.max_unknowns, plan.predicted_unknowns);
        history.stop_reason = buf;
      }
    }
    history.passes.back().seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (on_pass)
      on_pass(history.passes.back());
    if (history.converged || !history.stop_reason.empty())
      return history;
  }
}

std::string adapt_warning(const AdaptHistory& h) {
  if (h.converged)
    return "";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "adaptive refinement stopped before reaching %.3g %%: %s; estimated energy "
                "error %.3g %%",
                h.accuracy_pct, h.stop_reason.c_str(), h.passes.back().energy_error_pct);
  return buf;
}

nlohmann::ordered_json adapt_json(const AdaptHistory& h) {
  nlohmann::ordered_json j;
  j["accuracy_pct"] = h.accuracy_pct;
  j["converged"] = h.converged;
  if (!h.converged)
    j["stop_reason"] = h.stop_reason;
  j["passes"] = nlohmann::ordered_json::array();
  for (const auto& p : h.passes) {
    nlohmann::ordered_json q = nlohmann::ordered_json::object(), e = q;
    for (std::size_t i = 0; i < p.quantities.size(); ++i) {
      q[p.quantities[i].first] = p.quantities[i].second;
      e[p.quantities[i].first] = number_or_null(p.quantity_error_pct[i]);
    }
    j["passes"].push_back({{"pass", p.pass},
                           {"elements", p.elements},
                           {"unknowns", p.unknowns},
                           {"energy_J", p.energy_J},
                           {"energy_error_pct", p.energy_error_pct},
                           {"delta_energy_pct", number_or_null(p.delta_energy_pct)},
                           {"quantities", q},
                           {"quantity_error_pct", e},
                           {"seconds", p.seconds}});
  }
  return j;
}

std::string describe_adapt_pass(const AdaptPass& p, const char* element_word) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "pass %-3d %zu %s, %d DOFs, energy %.7g, error %.3g %%", p.pass,
                p.elements, element_word, p.unknowns, p.energy_J, p.energy_error_pct);
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

std::string describe_adapt_result(const AdaptHistory& a) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "adapt    %s %.3g %% after %zu pass(es)\n",
                a.converged ? "reached" : "did NOT reach", a.accuracy_pct, a.passes.size());
  return buf;
}

} // namespace magfem
