#pragma once
// The share of a part a model keeps under symmetry planes, for 2D and 3D: a plane that cuts
// the part (its interior points lie on both sides) keeps half of it, so the whole part is
// 2^(planes cutting it) times the meshed share. A part beside a plane is whole; a part beyond
// one is not kept at all.
#include <vector>

namespace magfem {

// xs: interior points of the part (Vec2 or Vec3); planes: anything with an `axis` member;
// tol: how far off a plane a point must be to count as on one side (metres).
template <class Point, class Plane>
double symmetry_cut_factor(const std::vector<Point>& xs, const std::vector<Plane>& planes,
                           double tol) {
  double factor = 1;
  for (const Plane& p : planes) {
    bool below = false, above = false;
    for (const Point& x : xs) {
      below = below || x[p.axis] < -tol;
      above = above || x[p.axis] > tol;
    }
    if (below && above)
      factor *= 2;
  }
  return factor;
}

// Whether the model keeps none of a part: every interior point lies beyond some plane (the
// mesher keeps the side where each plane's coordinate is >= 0). Such a part is not meshed;
// its mirror image in the share stands for it.
template <class Point, class Plane>
bool wholly_beyond_planes(const std::vector<Point>& xs, const std::vector<Plane>& planes,
                          double tol) {
  for (const Point& x : xs) {
    bool kept = true;
    for (const Plane& p : planes)
      kept = kept && x[p.axis] > -tol;
    if (kept)
      return false;
  }
  return !xs.empty();
}

} // namespace magfem
