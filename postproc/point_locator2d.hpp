#pragma once
// Finds the triangle containing a point (uniform bucket grid over the bounding box).
// Shell triangles are skipped: probes sample the physical domain only.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh2d.hpp"

namespace magfem {

struct PointLocation2D {
  std::size_t triangle;
  std::array<double, 3> bary;
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
