#pragma once
// The CSV tables of one solve, planar, axisymmetric and 3D alike, staged beside its VTU and
// summary.json: one CSV per probe first; forces.csv and sections.csv last, when there are any.
#include <vector>

#include "casefile/case_spec.hpp"
#include "core/output_stage.hpp"
#include "pipeline/force_results.hpp"
#include "pipeline/section_results.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

inline void stage_probe_tables(OutputStage& stage, const std::vector<ProbeTable>& probes) {
  for (const auto& p : probes)
    stage.write_text(p.name + ".csv", p.to_csv());
}

inline void stage_force_and_section_tables(OutputStage& stage,
                                           const std::vector<ForceResult>& forces,
                                           const std::vector<SectionFlux>& sections,
                                           const std::vector<RegionSpec>& regions) {
  if (!forces.empty())
    stage.write_text("forces.csv", forces_csv(forces));
  if (!sections.empty())
    stage.write_text("sections.csv", sections_csv(sections, regions));
}

} // namespace magfem
