#pragma once
// Section fluxes of one 3D run (postproc/section_flux3d.hpp) as written to sections.csv and
// summary.json. CSV contract (columns are only ever added at the end):
//   section,region,region_id,flux_Wb,area_m2,Bn_avg_T,B_avg_T
// Per section (in case-file order): one row per region the section crosses, in ascending
// region_id (the index of the case's region, -1 for the background air, named "air"), then
// its total row with region "total" and an empty region_id. flux_Wb is the integral of B.n
// (n the section's normal), area_m2 the area inside that region, Bn_avg_T = flux / area and
// B_avg_T the area average of |B|. SI units whatever the case's length unit.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "postproc/section_flux3d.hpp"

namespace magfem {

// `regions`: the case's regions, naming the region ids.
std::string sections_csv(const std::vector<SectionFlux>& sections,
                         const std::vector<RegionSpec>& regions);
// [{name, type, flux_Wb, area_m2, Bn_avg_T, B_avg_T, regions: [{name, region_id, ...}]}]
nlohmann::ordered_json sections_json(const std::vector<SectionFlux>& sections,
                                     const std::vector<SectionSpec>& specs,
                                     const std::vector<RegionSpec>& regions);
// Throws InputError at the section's line when part of it lies outside the physical mesh
// (in the open boundary's exterior shell or beyond the faceted outer sphere).
void check_sections_inside(const std::vector<SectionFlux>& sections, const CaseSpec& spec);

} // namespace magfem
