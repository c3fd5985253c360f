#include "mesh/region_overlap2d.hpp"

#include <algorithm>
#include <cstdio>
#include <list>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include "mesh/mesh_error.hpp"

namespace magfem {
namespace {

// Exact constructions: the intersection's vertices are computed exactly, so an area of zero
// for parts that only touch is exactly zero, not round-off.
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

Polygon polygon_of(const std::vector<Vec2>& loop, CGAL::Orientation want) {
  Polygon p;
  for (const Vec2& v : loop)
    p.push_back(K::Point_2(v.x(), v.y()));
  if (p.orientation() != want)
    p.reverse_orientation();
  return p;
}

PolygonWithHoles with_holes(const Outline2D& o) {
  const auto& loops = o.loops();
  PolygonWithHoles p(polygon_of(loops.front(), CGAL::COUNTERCLOCKWISE));
  for (std::size_t i = 1; i < loops.size(); ++i)
    p.add_hole(polygon_of(loops[i], CGAL::CLOCKWISE));
  return p;
}

bool boxes_apart(const Outline2D& a, const Outline2D& b) {
  return (a.box_max().array() < b.box_min().array()).any() ||
         (b.box_max().array() < a.box_min().array()).any();
}

} // namespace

std::pair<double, Vec2> shared_area2d(const Outline2D& a, const Outline2D& b) {
  if (boxes_apart(a, b))
    return {0.0, Vec2::Zero()};
  std::list<PolygonWithHoles> pieces;
  CGAL::intersection(with_holes(a), with_holes(b), std::back_inserter(pieces));
  double area = 0, largest = 0;
  Vec2 point = Vec2::Zero();
  for (const auto& piece : pieces) {
    double piece_area = CGAL::to_double(piece.outer_boundary().area());
    for (auto h = piece.holes_begin(); h != piece.holes_end(); ++h)
      piece_area += CGAL::to_double(h->area()); // holes are clockwise: negative areas
    area += piece_area;
    if (piece_area <= largest)
      continue;
    largest = piece_area;
    // The centroid of the widest triangle of the largest piece's fan: inside a convex
    // piece, near a general one (the point is a hint for the message).
    const auto& outer = piece.outer_boundary();
    double best = 0;
    for (std::size_t i = 1; i + 1 < outer.size(); ++i) {
      const K::Triangle_2 t(outer[0], outer[i], outer[i + 1]);
      const double ta = CGAL::to_double(t.area());
      if (ta > best) {
        best = ta;
        const auto c = CGAL::centroid(t);
        point = Vec2(CGAL::to_double(c.x()), CGAL::to_double(c.y()));
      }
    }
  }
  return {area, point};
}

std::optional<RegionOverlap2D> find_region_overlap2d(const std::vector<Part2D>& parts,
                                                     const std::vector<Outline2D>& outlines) {
  constexpr double sliver = 1e-9; // of the smaller part's area
  for (std::size_t j = 0; j < parts.size(); ++j) {
    if (parts[j].replace_earlier)
      continue;
    for (std::size_t i = j; i-- > 0;) { // the latest first: it owns the area if any does
      const auto [area, point] = shared_area2d(outlines[i], outlines[j]);
      const double smaller = std::min(outlines[i].polygon_area(), outlines[j].polygon_area());
      if (area > sliver * smaller)
        return RegionOverlap2D{i, j, area, point};
    }
  }
  return std::nullopt;
}

void check_region_overlaps2d(const Geometry2D& g, const RegionMap2D& map) {
  std::vector<Outline2D> outlines;
  for (std::size_t i = 0; i < map.n_parts(); ++i)
    outlines.push_back(map.part(i));
  const auto o = find_region_overlap2d(g.parts, outlines);
  if (!o)
    return;
  char what[160];
  std::snprintf(what, sizeof what, "%.4g mm^2 around (%.4g, %.4g) mm", o->area * 1e6,
                o->point.x() * 1e3, o->point.y() * 1e3);
  throw MeshError(g.parts[o->later].name, "",
                  "region '" + g.parts[o->later].name + "' overlaps region '" +
                      g.parts[o->earlier].name + "' (" + what +
                      "); regions must not share area unless the later one says "
                      "'overlap: replace' (it then takes that area from the earlier ones)");
}

} // namespace magfem
