#pragma once
// Finds the tetrahedron containing a point (uniform bucket grid over the bounding box of the
// physical tets; points beyond a symmetry plane of the mesh are found at their mirror image,
// PointLocation3D::b_map). Shell tets are skipped: probes sample the physical domain only. A point
// a hair outside the faceted boundary of the domain (a probe on the exact sphere) is given to the
// nearest tet of its bucket; further out it is reported as not found.
#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh3d.hpp"

namespace magfem {

struct PointLocation3D {
  std::size_t tet;
  std::array<double, 4> bary;
  // A mesh cut at symmetry planes (Mesh3D::symmetry) locates the point's mirror image on the
  // model's side; B (and H) at the asked point is b_map times the field found there.
  Eigen::Matrix3d b_map = Eigen::Matrix3d::Identity();
};

class PointLocator3D {
public:
  explicit PointLocator3D(const Mesh3D& mesh);
  // Only for points inside the bounding box of `points` (after folding): the grid covers the
  // tets that reach into that box, not the whole mesh (2116 probe points on benchmark32's
  // 1.6 M tets: a few thousand tets indexed instead of all). A tet containing such a point
  // reaches into the box, so those points are found as by the whole-mesh locator; a point
  // outside the box must not be asked.
  PointLocator3D(const Mesh3D& mesh, const std::vector<Eigen::Vector3d>& points);
  std::optional<PointLocation3D> locate(const Eigen::Vector3d& x) const;

private:
  // The grid over the tets `keep` accepts (non-shell tets whose box meets [lo, hi]).
  void index(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  std::array<int, 3> cell_of(const Eigen::Vector3d& x) const;
  std::size_t bucket_index(const std::array<int, 3>& c) const {
    return (static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
  }
  const Mesh3D& mesh_;
  Eigen::Vector3d lo_, cell_size_;
  std::array<int, 3> n_ = {1, 1, 1};
  std::vector<int> start_; // CSR buckets: tets of bucket b are items_[start_[b]..start_[b+1])
  std::vector<int> items_;
};

} // namespace magfem
