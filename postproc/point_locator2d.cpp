#include "postproc/point_locator2d.hpp"

#include <algorithm>
#include <cmath>

namespace magfem {

PointLocator2D::PointLocator2D(const Mesh2D& mesh) : mesh_(mesh) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (const auto& p : mesh.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // About two triangles per bucket keeps queries O(1).
  const double cells = std::max(1.0, static_cast<double>(mesh.n_triangles()) / 2.0);
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-30);
  const double h = std::sqrt(extent.x() * extent.y() / cells);
  nx_ = std::max(1, static_cast<int>(std::ceil(extent.x() / h)));
  ny_ = std::max(1, static_cast<int>(std::ceil(extent.y() / h)));
  lo_ = lo;
  cell_size_ = {extent.x() / nx_, extent.y() / ny_};
  buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (mesh.triangle_part[t] == region_shell) continue;
    const auto& tri = mesh.triangles[t];
    Eigen::Vector2d a = mesh.nodes[tri[0]], b = a;
    for (int k = 1; k < 3; ++k) {
      a = a.cwiseMin(mesh.nodes[tri[k]]);
      b = b.cwiseMax(mesh.nodes[tri[k]]);
    }
    const auto c0 = cell_of(a), c1 = cell_of(b);
    for (int i = c0[0]; i <= c1[0]; ++i)
      for (int j = c0[1]; j <= c1[1]; ++j) buckets_[j * nx_ + i].push_back(static_cast<int>(t));
  }
}

std::array<int, 2> PointLocator2D::cell_of(const Eigen::Vector2d& x) const {
  const int i = static_cast<int>(std::floor((x.x() - lo_.x()) / cell_size_.x()));
  const int j = static_cast<int>(std::floor((x.y() - lo_.y()) / cell_size_.y()));
  return {std::clamp(i, 0, nx_ - 1), std::clamp(j, 0, ny_ - 1)};
}

std::optional<PointLocation2D> PointLocator2D::locate(const Eigen::Vector2d& x_asked) const {
  const FoldedPoint2D folded = fold_point_2d(mesh_.symmetry, x_asked);
  const Eigen::Vector2d& x = folded.point;
  const auto c = cell_of(x);
  std::optional<PointLocation2D> best;
  // Points a hair outside the polygonal boundary (a probe on the exact circle) are taken by
  // the nearest triangle; further out they are reported as not found.
  double best_min = -0.05;
  for (int t : buckets_[c[1] * nx_ + c[0]]) {
    const auto& tri = mesh_.triangles[t];
    const Eigen::Vector2d p0 = mesh_.nodes[tri[0]], p1 = mesh_.nodes[tri[1]], p2 = mesh_.nodes[tri[2]];
    const double det = (p1 - p0).x() * (p2 - p0).y() - (p2 - p0).x() * (p1 - p0).y();
    const double l1 = ((x - p0).x() * (p2 - p0).y() - (p2 - p0).x() * (x - p0).y()) / det;
    const double l2 = ((p1 - p0).x() * (x - p0).y() - (x - p0).x() * (p1 - p0).y()) / det;
    const double l0 = 1 - l1 - l2;
    const double m = std::min({l0, l1, l2});
    if (m >= best_min) {
      best_min = m;
      best =
          PointLocation2D{static_cast<std::size_t>(t), {l0, l1, l2}, folded.b_map, folded.a_sign};
    }
  }
  return best;
}

} // namespace magfem
