#pragma once
// Finds the triangle containing a point (uniform bucket grid over the bounding box); points
// beyond a symmetry plane of the mesh are found at their mirror image (b_map, a_sign). Shell
// triangles are skipped: probes sample the physical domain only.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh2d.hpp"

namespace magfem {

struct PointLocation2D {
  std::size_t triangle;
  std::array<double, 3> bary;
  // A mesh cut at symmetry planes (Mesh2D::symmetry) locates the point's mirror image on the
  // model's side; B (and H) at the asked point is b_map times the field found there, A is
  // a_sign times the potential there (mesh/symmetry_plane2d.hpp).
  Eigen::Matrix2d b_map = Eigen::Matrix2d::Identity();
  double a_sign = 1;
};

class PointLocator2D {
public:
  explicit PointLocator2D(const Mesh2D& mesh);
  std::optional<PointLocation2D> locate(const Eigen::Vector2d& x) const;

private:
  std::array<int, 2> cell_of(const Eigen::Vector2d& x) const;
  const Mesh2D& mesh_;
  Eigen::Vector2d lo_, cell_size_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> buckets_;
};

} // namespace magfem
