#include "mesh/mesh_estimate3d.hpp"

#include <algorithm>
#include <cmath>

namespace magfem {

// Calibrated: TetGen made 1 / 0.49 times the tetrahedra a value of 16 predicted (geometric
// mean over the 3D examples and a box magnet at several mesh scales, docs/performance.md "Memory
// guard calibration").
const double tets_per_h3 = 32.6;

namespace {

// The recursion stops refining past this many cells: the estimate is then a lower bound,
// already far beyond any mesh this machine could hold.
constexpr long max_cells = 4'000'000;

struct Octree {
  const std::function<double(const Vec3&)>& size;
  double ball_radius;
  const std::vector<double>& within_radii;
  MeshEstimate3D result;

  void visit(const Vec3& centre, double side) {
    // Cells wholly outside the ball hold no elements.
    if (centre.norm() - 0.87 * side > ball_radius)
      return;
    const double h = size(centre);
    if (side > h && result.octree_cells < max_cells) {
      const double q = side / 4;
      for (int i = 0; i < 8; ++i)
        visit(centre + Vec3((i & 1) ? q : -q, (i & 2) ? q : -q, (i & 4) ? q : -q), side / 2);
      return;
    }
    ++result.octree_cells;
    const double inside = inside_fraction(ball_radius, centre, side);
    const double density = tets_per_h3 * std::pow(side / h, 3); // of the whole cell
    result.tetrahedra += inside * density;
    for (std::size_t i = 0; i < within_radii.size(); ++i)
      result.tetrahedra_within[i] +=
          std::min(inside, inside_fraction(within_radii[i], centre, side)) * density;
  }

  // A cell a sphere cuts counts by the fraction of its volume inside, from its centre's
  // distance to the sphere (a plane through the cell at that distance).
  static double inside_fraction(double radius, const Vec3& centre, double side) {
    const double d = (radius - centre.norm()) / side; // > 0: centre inside
    return std::clamp(0.5 + d, 0.0, 1.0);
  }
};

} // namespace

MeshEstimate3D estimate_mesh_3d(const std::function<double(const Vec3&)>& size, double ball_radius,
                                const std::vector<double>& within_radii) {
  Octree tree{size, ball_radius, within_radii, {}};
  tree.result.tetrahedra_within.assign(within_radii.size(), 0.0);
  tree.visit(Vec3::Zero(), 2 * ball_radius);
  tree.result.nodes = tree.result.tetrahedra / 5.5;
  return tree.result;
}

} // namespace magfem
