#pragma once
// The mesh warnings of a sweep's FE positions, said once per kind rather than once per
// position: the compensator's 8 positions printed the same unresolved-gap warning 8 times
// (gap widths 0.943-0.954 mm), --quiet or not. Warnings of one kind differ only in their
// figures (a rotated part's gap is a little wider or narrower), so the kind is the text with
// every number masked; each kind is said with the positions it applies to and the text of the
// first of them.
#include <string>
#include <utility>
#include <vector>

namespace magfem {

// `positions`: every solved position (its value, as in sweep.csv) and its mesh's warnings, in
// the sweep's order (those without warnings count in "k of n positions"). `key`: the
// positions' column name ("angle_deg", "position_mm").
std::vector<std::string>
grouped_mesh_warnings(const std::string& key,
                      const std::vector<std::pair<double, std::vector<std::string>>>& positions);

} // namespace magfem
