#include "studies/position_adapt.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace magfem {

void aim_adapt_at(CaseSpec& spec, const std::string& force_name, const std::string& component) {
  if (spec.adapt.enabled())
    spec.adapt.quantities = {"forces." + force_name + "." + component};
}

PositionAdapt position_adapt(const std::optional<AdaptHistory>& history) {
  if (!history || history->passes.empty())
    return {};
  const AdaptPass& last = history->passes.back();
  return {static_cast<int>(history->passes.size()), history->converged,
          last.quantity_error_pct.empty() ? last.energy_error_pct
                                          : last.quantity_error_pct.front()};
}

double position_adapt_error(const PositionAdapt& a, double magnitude) {
  return a.passes && std::isfinite(a.error_pct) ? a.error_pct / 100 * std::abs(magnitude)
                                                : std::numeric_limits<double>::quiet_NaN();
}

void add_position_adapt(nlohmann::json& row, const PositionAdapt& a) {
  row["adapt_passes"] = a.passes;
  row["adapt_converged"] = a.converged;
  row["adapt_error_pct"] =
      std::isfinite(a.error_pct) ? nlohmann::json(a.error_pct) : nlohmann::json(nullptr);
}

PositionAdapt position_adapt_from_json(const nlohmann::json& row) {
  PositionAdapt a;
  a.passes = row.value("adapt_passes", 0);
  a.converged = row.value("adapt_converged", false);
  const auto pct = row.find("adapt_error_pct");
  if (pct != row.end())
    a.error_pct = pct->is_number() ? pct->get<double>() : std::numeric_limits<double>::quiet_NaN();
  return a;
}

nlohmann::ordered_json position_adapt_summary(const PositionAdapt& a) {
  return {{"passes", a.passes},
          {"converged", a.converged},
          {"estimated_error_pct", std::isfinite(a.error_pct) ? nlohmann::ordered_json(a.error_pct)
                                                             : nlohmann::ordered_json(nullptr)}};
}

std::string position_adapt_warning(const std::string& key, double position,
                                   const PositionAdapt& a) {
  if (!a.passes || a.converged)
    return "";
  char line[240];
  std::snprintf(line, sizeof line,
                "%s %g: adaptive refinement stopped after %d pass(es) before reaching its "
                "accuracy (estimated error %.3g %%)",
                key.c_str(), position, a.passes, a.error_pct);
  return line;
}

} // namespace magfem
