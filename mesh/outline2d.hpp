#pragma once
// Polygonal approximation of one 2D primitive: the loops that become CGAL constraints, and a
// point-in-shape test that answers for exactly those polygons (not for the exact curves), so
// that region assignment agrees with the constrained edges of the mesh.
//
// Arcs are cut by a CircleSet2D shared by all parts (see circle_set2d.hpp): each arc asks for
// chords that satisfy all of
//   sagitta r (1 - cos(dphi / 2)) <= chord_tolerance,
//   chord length <= the chord limit sampled along the arc,
//   at least 8 chords per full turn,
// and parts meeting on a circle share its vertices. Straight edges are split uniformly so that
// no piece exceeds the chord limit sampled along it; the split points of an edge do not depend
// on its direction, so edges shared by two parts coincide exactly.
//
// Building is two-phase because arcs of all parts must be known before any circle is cut:
//   CircleSet2D circles;  OutlineBuilder2D b(part, tol, limit, circles);  (for every part)
//   circles.finalize();   Outline2D o = b.build(shared circles);
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/circle_set2d.hpp"
#include "mesh/geometry2d.hpp"

namespace magfem {

// Longest boundary chord wanted at a point (metres), e.g. the local mesh size.
using ChordLimit2D = std::function<double(const Vec2&)>;

class Outline2D {
public:
  // Closed loops; the first is the outer boundary, further loops are holes (annulus).
  const std::vector<std::vector<Vec2>>& loops() const { return loops_; }
  // True when p lies strictly inside the polygonal approximation (round-off aside).
  bool contains(const Vec2& p) const;
  double polygon_area() const; // m^2, area enclosed by loops() (holes subtracted)
  double exact_area() const;   // m^2, area of the exact primitive
  double max_sagitta() const { return max_sagitta_; } // metres, 0 for straight-sided shapes
  Vec2 box_min() const { return lo_; }
  Vec2 box_max() const { return hi_; }

private:
  friend class OutlineBuilder2D;

  Shape2D shape_;
  std::shared_ptr<const CircleSet2D> circles_;
  int outer_circle_ = -1, inner_circle_ = -1; // circle ids, -1 when absent
  bool sector_ = false;                       // a true sector: wedge test plus radial edges
  Vec2 sector_center_ = Vec2::Zero();
  double sector_start_ = 0, sector_span_ = 0;
  std::vector<std::vector<Vec2>> loops_;
  std::vector<std::vector<int>> edge_bands_; // polygon edges by horizontal band (contains())
  double max_sagitta_ = 0;
  Vec2 lo_ = Vec2::Zero(), hi_ = Vec2::Zero();
};

class OutlineBuilder2D {
public:
  // Validates the part (throws MeshError naming the part and field for zero or negative radii,
  // r_inner >= r_outer, empty angular spans, polygons with fewer than 3 vertices, repeated
  // vertices, zero area or self-intersections, a negative max_size) and requests its arcs.
  OutlineBuilder2D(const Part2D& part, double chord_tolerance, ChordLimit2D limit,
                   CircleSet2D& circles);
  // After circles.finalize(): the outline.
  Outline2D build(const std::shared_ptr<const CircleSet2D>& circles) const;

private:
  [[noreturn]] void fail(const std::string& field, const std::string& msg) const;
  void check_center(const Vec2& c) const;
  void check_radii(double r_inner, double r_outer) const;
  void check_simple(const std::vector<Vec2>& v) const;
  int request_arc(CircleSet2D& circles, const Vec2& c, double r, double a0, double span) const;
  void append_segment(std::vector<Vec2>& loop, Vec2 a, Vec2 b) const;
  std::vector<Vec2> close_polyline(const std::vector<Vec2>& corners) const;
  void add_arcs(Outline2D& o, const CircleSet2D& circles) const;
  static void bin_edges(Outline2D& o, const std::vector<Vec2>& v);

  Part2D part_;
  double tol_;
  ChordLimit2D limit_;
  int outer_arc_ = -1, inner_arc_ = -1;
};

} // namespace magfem
