#pragma once
// The demagnetization check of a solve (postproc/demagnetization.hpp) in the pipeline's
// outputs, the same for 2D, axisymmetric and 3D: summary.json's `demagnetization` block, the
// VTU's `B_along_M` cell field and a console warning per magnet past its knee.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "postproc/demagnetization.hpp"
#include "postproc/field2d.hpp"
#include "postproc/field3d.hpp"
#include "postproc/vtu_writer.hpp"

namespace magfem {

// The check of every magnet region of the case; each one at risk adds a line to `warnings`.
DemagnetizationResult check_demagnetization(const Field2D& field, const CaseSpec& spec,
                                            std::vector<std::string>& warnings);
DemagnetizationResult check_demagnetization(const Field3D& field, const CaseSpec& spec,
                                            std::vector<std::string>& warnings);

// summary.json's "demagnetization" (set only when the case has magnets): per magnet region
// {region, material, temperature_C, min_B_along_M_T, at_mm, knee_T, margin_T, at_risk};
// at_mm has the solve's coordinates ([x, y], [r, z] or [x, y, z]) in mm; knee_T and margin_T
// are null for a grade without knee data.
void add_demagnetization(nlohmann::ordered_json& summary, const DemagnetizationResult& result,
                         int dimension);

// The `B_along_M` cell field (T; NaN outside magnets), for the cells the VTU writes: every
// element but those is_shell names.
void add_B_along_M(VtuGrid& grid, const DemagnetizationResult& result,
                   const std::function<bool(std::size_t)>& is_shell);

} // namespace magfem
