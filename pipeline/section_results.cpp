#include "pipeline/section_results.hpp"

#include <cstdio>

#include "core/input_error.hpp"

namespace magfem {
namespace {

std::string region_name(int region, const std::vector<RegionSpec>& regions) {
  return region >= 0 && region < static_cast<int>(regions.size()) ? regions[region].name : "air";
}

std::string numbers(const SectionPart& p) {
  char buf[120];
  std::snprintf(buf, sizeof buf, "%.10g,%.10g,%.10g,%.10g", p.flux_Wb, p.area_m2, p.Bn_avg_T(),
                p.B_avg_T());
  return buf;
}

nlohmann::ordered_json part_json(const SectionPart& p) {
  return {{"flux_Wb", p.flux_Wb},
          {"area_m2", p.area_m2},
          {"Bn_avg_T", p.Bn_avg_T()},
          {"B_avg_T", p.B_avg_T()}};
}

} // namespace

std::string sections_csv(const std::vector<SectionFlux>& sections,
                         const std::vector<RegionSpec>& regions) {
  std::string out = "section,region,region_id,flux_Wb,area_m2,Bn_avg_T,B_avg_T\n";
  for (const auto& s : sections) {
    for (const auto& p : s.parts)
      out += s.name + "," + region_name(p.region, regions) + "," + std::to_string(p.region) + "," +
             numbers(p) + "\n";
    out += s.name + ",total,," + numbers(s.total) + "\n";
  }
  return out;
}

nlohmann::ordered_json sections_json(const std::vector<SectionFlux>& sections,
                                     const std::vector<SectionSpec>& specs,
                                     const std::vector<RegionSpec>& regions) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const SectionFlux& s = sections[i];
    nlohmann::ordered_json j = {{"name", s.name},
                                {"type", specs[i].kind == SectionSpec::Kind::disk   ? "disk"
                                         : specs[i].kind == SectionSpec::Kind::line ? "line"
                                                                                    : "rectangle"}};
    j.update(part_json(s.total));
    j["regions"] = nlohmann::ordered_json::array();
    for (const auto& p : s.parts) {
      nlohmann::ordered_json r = {{"name", region_name(p.region, regions)},
                                  {"region_id", p.region}};
      r.update(part_json(p));
      j["regions"].push_back(r);
    }
    out.push_back(j);
  }
  return out;
}

void check_sections_inside(const std::vector<SectionFlux>& sections, const CaseSpec& spec) {
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const SectionFlux& s = sections[i];
    // Round-off of summing a few thousand polygon areas stays far below 1e-9.
    if (s.outside_area_m2 <= 1e-9 * s.nominal_area_m2)
      continue;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "section '%s' leaves the meshed domain: %.3g %% of its area lies outside "
                  "the faceted outer boundary (move it inwards or enlarge the boundary radius)",
                  s.name.c_str(), 100 * s.outside_area_m2 / s.nominal_area_m2);
    throw InputError(spec.file, spec.sections[i].line, "sections[" + std::to_string(i) + "]", buf);
  }
}

} // namespace magfem
