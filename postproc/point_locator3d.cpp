#include "postproc/point_locator3d.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace magfem {

namespace {

// The bounding box of tet t.
std::pair<Eigen::Vector3d, Eigen::Vector3d> tet_box(const Mesh3D& mesh, std::size_t t) {
  Eigen::Vector3d a = mesh.nodes[mesh.tets[t][0]], b = a;
  for (int k = 1; k < 4; ++k) {
    a = a.cwiseMin(mesh.nodes[mesh.tets[t][k]]);
    b = b.cwiseMax(mesh.nodes[mesh.tets[t][k]]);
  }
  return {a, b};
}

bool boxes_meet(const Eigen::Vector3d& a_lo, const Eigen::Vector3d& a_hi,
                const Eigen::Vector3d& b_lo, const Eigen::Vector3d& b_hi) {
  return (a_lo.array() <= b_hi.array()).all() && (b_lo.array() <= a_hi.array()).all();
}

} // namespace

PointLocator3D::PointLocator3D(const Mesh3D& mesh) : mesh_(mesh) {
  const Eigen::Vector3d everywhere = Eigen::Vector3d::Constant(1e300);
  index(-everywhere, everywhere);
}

PointLocator3D::PointLocator3D(const Mesh3D& mesh, const std::vector<Eigen::Vector3d>& points)
    : mesh_(mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const Eigen::Vector3d& x : points) {
    const Eigen::Vector3d p = fold_point(mesh.symmetry, x).point;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  index(lo, hi);
}

void PointLocator3D::index(const Eigen::Vector3d& region_lo, const Eigen::Vector3d& region_hi) {
  const Mesh3D& mesh = mesh_;
  std::vector<int> kept;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (mesh.tet_part[t] == region_shell_3d)
      continue;
    const auto [a, b] = tet_box(mesh, t);
    if (!boxes_meet(a, b, region_lo, region_hi))
      continue;
    kept.push_back(static_cast<int>(t));
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  if (kept.empty())
    lo = hi = Eigen::Vector3d::Zero();
  // About two tets per bucket keeps queries O(1).
  const double cells = std::max(1.0, static_cast<double>(kept.size()) / 2.0);
  const Eigen::Vector3d extent = (hi - lo).cwiseMax(1e-30);
  const double h = std::cbrt(extent.prod() / cells);
  for (int k = 0; k < 3; ++k)
    n_[k] = std::clamp(static_cast<int>(std::ceil(extent[k] / h)), 1, 2048);
  lo_ = lo;
  cell_size_ = {extent.x() / n_[0], extent.y() / n_[1], extent.z() / n_[2]};

  // Two passes (count, then fill) into CSR storage: no per-bucket allocations.
  const std::size_t n_buckets = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
  start_.assign(n_buckets + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (std::size_t b = 0; b < n_buckets; ++b)
        start_[b + 1] += start_[b];
      items_.resize(start_[n_buckets]);
      fill.assign(start_.begin(), start_.end() - 1);
    }
    for (int t : kept) {
      const auto [a, b] = tet_box(mesh, static_cast<std::size_t>(t));
      const auto c0 = cell_of(a), c1 = cell_of(b);
      for (int k = c0[2]; k <= c1[2]; ++k)
        for (int j = c0[1]; j <= c1[1]; ++j)
          for (int i = c0[0]; i <= c1[0]; ++i) {
            const std::size_t bi = bucket_index({i, j, k});
            if (pass == 0)
              ++start_[bi + 1];
            else
              items_[fill[bi]++] = t;
          }
    }
  }
}

std::array<int, 3> PointLocator3D::cell_of(const Eigen::Vector3d& x) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k)
    c[k] = std::clamp(static_cast<int>(std::floor((x[k] - lo_[k]) / cell_size_[k])), 0, n_[k] - 1);
  return c;
}

std::optional<PointLocation3D> PointLocator3D::locate(const Eigen::Vector3d& x_asked) const {
  const FoldedPoint3D folded = fold_point(mesh_.symmetry, x_asked);
  const Eigen::Vector3d& x = folded.point;
  const std::size_t b = bucket_index(cell_of(x));
  std::optional<PointLocation3D> best;
  double best_min = -0.05;
  for (int i = start_[b]; i < start_[b + 1]; ++i) {
    const auto& tet = mesh_.tets[items_[i]];
    const Eigen::Vector3d p0 = mesh_.nodes[tet[0]];
    Eigen::Matrix3d j;
    j << mesh_.nodes[tet[1]] - p0, mesh_.nodes[tet[2]] - p0, mesh_.nodes[tet[3]] - p0;
    const Eigen::Vector3d l = j.inverse() * (x - p0);
    const double l0 = 1 - l.sum();
    const double m = std::min({l0, l.x(), l.y(), l.z()});
    if (m >= best_min) {
      best_min = m;
      best = PointLocation3D{
          static_cast<std::size_t>(items_[i]), {l0, l.x(), l.y(), l.z()}, folded.b_map};
      if (m >= 0)
        break; // inside: no other tet can do better than a containing one
    }
  }
  return best;
}

} // namespace magfem
