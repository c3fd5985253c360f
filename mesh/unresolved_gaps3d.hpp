#pragma once
// Air gaps between two parts that the mesh leaves unresolved: elements across a gap whose nodes
// (an element of size h has them h / order apart) are farther apart than the gap is wide. The
// mesher records the narrowest such place per pair of parts (mesher3d.cpp); this turns them
// into the mesh's warnings. A warning, not a refusal: the mesh is valid and the answer usable
// (a coarse --mesh-scale run is often a deliberate first look or a convergence study's
// coarsest step), but the field in the gap, and a force across it, are not resolved.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/placement3d.hpp"

namespace magfem {

// Per pair of parts: the narrowest unresolved place of their gap (m), the element size across
// it (m), and the middle of the gap there.
struct UnresolvedGap {
  double width = 0;
  double across = 0;
  Vec3 middle = Vec3::Zero();
};
// By pair of part indices (first < second).
using UnresolvedGaps = std::map<std::pair<int, int>, UnresolvedGap>;

// One warning per pair of parts, except that the gaps one part has with several others (an
// iron shell 1 mm outside 32 magnets) are said in one warning naming them. `scale`: the sizes'
// scale in all (the case's mesh scale times --mesh-scale).
std::vector<std::string> unresolved_gap_warnings(const std::vector<std::string>& part_names,
                                                 int order, int gap_layers, double scale,
                                                 const UnresolvedGaps& unresolved);

} // namespace magfem
