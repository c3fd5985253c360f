#pragma once
// Polygonal approximation of one 2D primitive: the loops that become CGAL constraints, and a
// point-in-shape test that answers for exactly those polygons (not for the exact curves), so
// that region assignment agrees with the constrained edges of the mesh.
//
// Arcs are cut into chords at uniformly spaced angles (a full circle starts at angle 0 about
// its centre). The chord count of each arc is the smallest that satisfies all of
//   sagitta r (1 - cos(dphi / 2)) <= chord_tolerance,
//   chord length <= the chord limit sampled along the arc,
//   at least 8 chords per full turn.
// Straight edges are split uniformly so that no piece exceeds the chord limit sampled along it.
#include <functional>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/geometry2d.hpp"

namespace magfem {

// Longest boundary chord wanted at a point (metres), e.g. the local mesh size.
using ChordLimit2D = std::function<double(const Vec2&)>;

class Outline2D {
public:
  // Validates the shape (throws MeshError naming the part and field for zero or negative radii,
  // r_inner >= r_outer, empty angular spans, polygons with fewer than 3 vertices, repeated
  // vertices, zero area or self-intersections) and discretises it.
  static Outline2D build(const Part2D& part, double chord_tolerance, const ChordLimit2D& limit);

  // Closed loops; the first is the outer boundary, further loops are holes (annulus).
  const std::vector<std::vector<Vec2>>& loops() const { return loops_; }
  // True when p lies strictly inside the polygonal approximation (round-off aside).
  bool contains(const Vec2& p) const;
  double polygon_area() const; // m^2, area enclosed by loops() (holes subtracted)
  double exact_area() const;   // m^2, area of the exact primitive
  double max_sagitta() const { return max_sagitta_; } // metres, 0 for straight-sided shapes
  Vec2 box_min() const { return lo_; }
  Vec2 box_max() const { return hi_; }

  // One arc of the approximation: vertices at angle_start + k * span / n_chords, k = 0..n.
  struct Arc {
    Vec2 center = Vec2::Zero();
    double radius = 0, angle_start = 0, span = 0;
    int n_chords = 0;
  };

private:
  bool inside_arc_chain(const Vec2& p, const Arc& arc) const;

  Shape2D shape_;
  bool kind_sector_ = false; // a true sector: wedge test plus radial edges
  std::vector<Arc> arcs_;    // outer arc first, inner arc second (annulus, sector)
  std::vector<std::vector<Vec2>> loops_;
  double max_sagitta_ = 0;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
  friend class OutlineBuilder2D;
};

} // namespace magfem
