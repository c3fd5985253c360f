#include "validation/validate_checkpoint.hpp"

#include <cmath>
#include <limits>

namespace magfem {
namespace {

nlohmann::json optional_number(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

std::optional<double> number_or_none(const nlohmann::json& j) {
  if (j.is_null())
    return std::nullopt;
  return j.get<double>();
}

nlohmann::json plots_to_json(const std::vector<Plot>& plots) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : plots) {
    nlohmann::json series = nlohmann::json::array();
    for (const auto& s : p.series)
      series.push_back({{"name", s.name}, {"x", s.x}, {"y", s.y}, {"points_only", s.points_only}});
    out.push_back(
        {{"title", p.title}, {"x_label", p.x_label}, {"y_label", p.y_label}, {"series", series}});
  }
  return out;
}

std::vector<Plot> plots_from_json(const nlohmann::json& j) {
  std::vector<Plot> plots;
  for (const auto& p : j) {
    Plot plot{p.at("title"), p.at("x_label"), p.at("y_label"), {}};
    for (const auto& s : p.at("series"))
      plot.series.push_back({s.at("name"), s.at("x").get<std::vector<double>>(),
                             s.at("y").get<std::vector<double>>(), s.at("points_only")});
    plots.push_back(std::move(plot));
  }
  return plots;
}

nlohmann::json adapt_to_json(const std::optional<FeAdaptOutcome>& a) {
  if (!a)
    return nullptr;
  return {{"accuracy_pct", a->accuracy_pct},
          {"passes", a->passes},
          {"converged", a->converged},
          {"stop_reason", a->stop_reason},
          {"estimate_pct",
           optional_number(std::isfinite(a->estimate_pct) ? std::optional<double>(a->estimate_pct)
                                                          : std::nullopt)}};
}

std::optional<FeAdaptOutcome> adapt_from_json(const nlohmann::json& j) {
  if (j.is_null())
    return std::nullopt;
  return FeAdaptOutcome{
      j.at("accuracy_pct"), j.at("passes"), j.at("converged"), j.at("stop_reason"),
      number_or_none(j.at("estimate_pct")).value_or(std::numeric_limits<double>::quiet_NaN())};
}

} // namespace

nlohmann::json entry_to_checkpoint(const EntryResult& r) {
  return {{"status", r.status},
          {"fe", optional_number(r.fe)},
          {"analytic", optional_number(r.analytic)},
          {"fe_error_pct", optional_number(r.fe_error_pct)},
          {"analytic_error_pct", optional_number(r.analytic_error_pct)},
          {"discretisation_pct", optional_number(r.discretisation_pct)},
          {"seconds", r.seconds},
          {"note", r.note},
          {"eval_fe", optional_number(r.eval.fe)},
          {"eval_analytic", optional_number(r.eval.analytic)},
          {"eval_fe_coarse", optional_number(r.eval.fe_coarse)},
          {"eval_fe_adapt", adapt_to_json(r.eval.fe_adapt)},
          {"eval_fe_unknowns",
           r.eval.fe_unknowns ? nlohmann::json(*r.eval.fe_unknowns) : nlohmann::json(nullptr)},
          {"method", r.eval.method},
          // As text: an ordered_json keeps its key order only through its own dump.
          {"details", r.eval.details.dump()},
          {"plots", plots_to_json(r.eval.plots)}};
}

void entry_from_checkpoint(const nlohmann::json& j, EntryResult& r) {
  r.status = j.at("status");
  r.fe = number_or_none(j.at("fe"));
  r.analytic = number_or_none(j.at("analytic"));
  r.fe_error_pct = number_or_none(j.at("fe_error_pct"));
  r.analytic_error_pct = number_or_none(j.at("analytic_error_pct"));
  r.discretisation_pct = number_or_none(j.at("discretisation_pct"));
  r.seconds = j.at("seconds");
  r.note = j.at("note");
  r.eval.fe = number_or_none(j.at("eval_fe"));
  r.eval.analytic = number_or_none(j.at("eval_analytic"));
  r.eval.fe_coarse = number_or_none(j.at("eval_fe_coarse"));
  r.eval.fe_adapt = adapt_from_json(j.at("eval_fe_adapt"));
  if (const auto& u = j.at("eval_fe_unknowns"); !u.is_null())
    r.eval.fe_unknowns = u.get<long>();
  r.eval.method = j.at("method");
  r.eval.details = nlohmann::ordered_json::parse(j.at("details").get<std::string>());
  r.eval.plots = plots_from_json(j.at("plots"));
}

} // namespace magfem
