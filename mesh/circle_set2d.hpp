#pragma once
// The circles of a 2D geometry as shared polygons. Parts that meet on a circle (a magnet ring on
// a yoke, sectors side by side) must use the very same chord vertices there, or the two
// polygonal approximations would cross each other in slivers of the sagitta's width.
//
// Every arc is first requested with the largest chord angle it allows; arcs on the same circle
// (same centre and radius to 1e-12 relative) are then merged into one polygon:
//   - a uniform grid of angles from 0 whose step is the smallest allowed chord angle on that
//     circle (so a circle alone is cut at uniformly spaced angles),
//   - every arc end (sector corner) replaces the grid angle nearest to it; the grid step is then
//     shrunk by 2/3 so that the chords next to a corner still respect every arc's limit.
// Each arc is the run of polygon vertices from its start corner to its end corner.
#include <vector>

#include "mesh/geometry2d.hpp"

namespace magfem {

class CircleSet2D {
public:
  // Requests an arc (span = 2 pi for a full circle) whose chords may subtend at most
  // max_chord_angle; returns the arc id.
  int request(const Vec2& center, double radius, double angle_start, double span,
              double max_chord_angle);
  // Builds the polygons; call once after every request.
  void finalize();

  // Vertices of an arc, counter-clockwise: a full circle's loop, or a sector arc from its start
  // corner to its end corner inclusive.
  std::vector<Vec2> arc_points(int arc) const;
  int circle_of(int arc) const { return arcs_[std::size_t(arc)].circle; }
  // Strictly inside the circle's polygon (round-off aside).
  bool inside(int circle, const Vec2& p) const;
  double max_sagitta(int circle) const;

private:
  struct Circle {
    Vec2 center;
    double radius = 0;
    double max_chord_angle = 0;
    bool has_corners = false;
    std::vector<double> angles; // sorted in [0, 2 pi)
    std::vector<Vec2> points;
  };
  struct Arc {
    int circle = 0;
    double start = 0, span = 0; // start wrapped to [0, 2 pi)
    int first = 0, last = 0;    // vertex indices of the corners (sector arcs)
  };

  int find_or_add(const Vec2& center, double radius);
  int nearest_vertex(const Circle& c, double angle) const;

  std::vector<Circle> circles_;
  std::vector<Arc> arcs_;
};

} // namespace magfem
