#pragma once
// Regions of a 2D geometry that share area. The mesher lets a later part win where parts
// overlap, which silently cuts a magnet or a coil when the overlap was a slip (a coil
// rectangle 1 mm too wide removed 4 mm^2 of a 25 mm^2 magnet). So overlap is an error unless
// the later part says it replaces (Part2D::replace_earlier: a slot cut into iron, a magnet
// inside its air band).
#include <optional>
#include <vector>

#include "mesh/geometry2d.hpp"
#include "mesh/outline2d.hpp"
#include "mesh/region_map2d.hpp"

namespace magfem {

struct RegionOverlap2D {
  std::size_t earlier = 0, later = 0; // part indices, earlier < later
  double area = 0;                    // m^2 shared by the two outlines
  Vec2 point = Vec2::Zero();          // about where they share it (a message's hint), metres
};

// The first pair (by later part, then by the earlier part from the latest back) whose outlines
// share more than a billionth of the smaller part's area (round-off slivers of edges that coincide
// only up to a rounding are not overlaps) where the later part does not replace earlier ones.
// outlines[i] is the polygonal outline of parts[i]; the areas are exact for those polygons (CGAL's
// exact Boolean operations), so parts that touch along an edge or a shared circle never count.
std::optional<RegionOverlap2D> find_region_overlap2d(const std::vector<Part2D>& parts,
                                                     const std::vector<Outline2D>& outlines);

// Throws MeshError naming the later part (and, in the message, the earlier one, the shared
// area in mm^2 and about where) for the first overlap find_region_overlap2d finds among the
// map's part outlines.
void check_region_overlaps2d(const Geometry2D& g, const RegionMap2D& map);

// The shared area (m^2) of two outlines, and about where it lies (when the area is > 0).
std::pair<double, Vec2> shared_area2d(const Outline2D& a, const Outline2D& b);

} // namespace magfem
