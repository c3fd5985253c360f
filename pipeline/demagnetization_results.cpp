#include "pipeline/demagnetization_results.hpp"

#include "postproc/demagnetization2d.hpp"
#include "postproc/demagnetization3d.hpp"

namespace magfem {

namespace {

std::vector<std::string> region_names(const CaseSpec& spec) {
  std::vector<std::string> names;
  for (const auto& r : spec.regions)
    names.push_back(r.name);
  return names;
}

DemagnetizationResult with_warnings(DemagnetizationResult result, const CaseSpec& spec,
                                    std::vector<std::string>& warnings) {
  for (const auto& c : result.magnets)
    if (c.at_risk)
      warnings.push_back(c.warning(spec.length_unit, spec.unit_name, spec.dimension));
  return result;
}

nlohmann::ordered_json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

} // namespace

DemagnetizationResult check_demagnetization(const Field2D& field, const CaseSpec& spec,
                                            std::vector<std::string>& warnings) {
  return with_warnings(check_demagnetization_2d(field, region_names(spec)), spec, warnings);
}

DemagnetizationResult check_demagnetization(const Field3D& field, const CaseSpec& spec,
                                            std::vector<std::string>& warnings) {
  return with_warnings(check_demagnetization_3d(field, region_names(spec)), spec, warnings);
}

void add_demagnetization(nlohmann::ordered_json& summary, const DemagnetizationResult& result,
                         int dimension) {
  if (result.magnets.empty())
    return;
  auto& block = summary["demagnetization"];
  block = nlohmann::ordered_json::array();
  for (const auto& c : result.magnets) {
    auto at = nlohmann::ordered_json::array();
    for (int i = 0; i < dimension; ++i)
      at.push_back(c.at_m[i] * 1e3);
    block.push_back({{"region", c.region},
                     {"material", c.material},
                     {"temperature_C", c.temperature_C},
                     {"min_B_along_M_T", c.min_B_along_M_T},
                     {"at_mm", at},
                     {"knee_T", optional_number(c.knee_T)},
                     {"margin_T", optional_number(c.margin_T)},
                     {"at_risk", c.at_risk}});
  }
}

void add_B_along_M(VtuGrid& grid, const DemagnetizationResult& result,
                   const std::function<bool(std::size_t)>& is_shell) {
  VtuArray a{"B_along_M", 1, {}};
  for (std::size_t t = 0; t < result.element_B_along_M.size(); ++t)
    if (!is_shell(t))
      a.values.push_back(result.element_B_along_M[t]);
  grid.cell_data.push_back(std::move(a));
}

} // namespace magfem
