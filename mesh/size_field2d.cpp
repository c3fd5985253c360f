#include "mesh/size_field2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace magfem {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr int max_cells_per_axis = 1024;

double point_segment_distance(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

} // namespace

SizeField2D::SizeField2D(std::function<double(const Vec2&)> region_size,
                         std::vector<SizeSource2D> sources, double grading, double floor,
                         const Vec2& box_min, const Vec2& box_max)
    : region_size_(std::move(region_size)), sources_(std::move(sources)), grading_(grading),
      floor_(floor), origin_(box_min) {
  const Vec2 extent = (box_max - box_min).cwiseMax(Vec2::Constant(1e-300));
  // Cells of about the typical source size keep the sources per cell few near fine features,
  // where most queries happen; the per-axis cap bounds memory.
  std::vector<double> sizes;
  for (const auto& s : sources_)
    sizes.push_back(std::max(s.size, (s.b - s.a).norm()));
  double typical = extent.maxCoeff() / 64;
  if (!sizes.empty()) {
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    typical = sizes[sizes.size() / 2];
  }
  cell_ = std::max(typical, extent.maxCoeff() / max_cells_per_axis);
  nx_ = std::clamp(int(std::ceil(extent.x() / cell_)), 1, max_cells_per_axis);
  ny_ = std::clamp(int(std::ceil(extent.y() / cell_)), 1, max_cells_per_axis);
  bucket_sources();
}

void SizeField2D::bucket_sources() {
  min_source_size_ = inf;
  const auto cell_range = [&](double lo, double hi, double o, int n) {
    return std::pair{std::clamp(int(std::floor((lo - o) / cell_)), 0, n - 1),
                     std::clamp(int(std::floor((hi - o) / cell_)), 0, n - 1)};
  };
  std::vector<int> count(std::size_t(nx_) * ny_ + 1, 0);
  const auto for_cells = [&](const SizeSource2D& s, auto&& f) {
    const auto [i0, i1] =
        cell_range(std::min(s.a.x(), s.b.x()), std::max(s.a.x(), s.b.x()), origin_.x(), nx_);
    const auto [j0, j1] =
        cell_range(std::min(s.a.y(), s.b.y()), std::max(s.a.y(), s.b.y()), origin_.y(), ny_);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        f(j * nx_ + i);
  };
  for (const auto& s : sources_) {
    min_source_size_ = std::min(min_source_size_, s.size);
    for_cells(s, [&](int c) { ++count[c + 1]; });
  }
  for (std::size_t c = 1; c < count.size(); ++c)
    count[c] += count[c - 1];
  cell_start_ = count;
  cell_items_.assign(count.back(), 0);
  cell_min_.assign(std::size_t(nx_) * ny_, inf);
  for (int k = 0; k < int(sources_.size()); ++k)
    for_cells(sources_[k], [&](int c) {
      cell_items_[count[c]++] = k;
      cell_min_[c] = std::min(cell_min_[c], sources_[k].size);
    });
}

double SizeField2D::cell_distance(const Vec2& x, int i, int j) const {
  const double x0 = origin_.x() + i * cell_, y0 = origin_.y() + j * cell_;
  const double dx = std::max({x0 - x.x(), 0.0, x.x() - x0 - cell_});
  const double dy = std::max({y0 - x.y(), 0.0, x.y() - y0 - cell_});
  return std::sqrt(dx * dx + dy * dy);
}

double SizeField2D::operator()(const Vec2& x) const {
  double best = region_size_(x);
  if (!sources_.empty()) {
    const int ci = std::clamp(int(std::floor((x.x() - origin_.x()) / cell_)), 0, nx_ - 1);
    const int cj = std::clamp(int(std::floor((x.y() - origin_.y()) / cell_)), 0, ny_ - 1);
    const int max_ring = std::max({ci, cj, nx_ - 1 - ci, ny_ - 1 - cj});
    const auto visit = [&](int i, int j) {
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_)
        return;
      const int c = j * nx_ + i;
      if (cell_min_[c] + grading_ * cell_distance(x, i, j) >= best)
        return;
      for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const SizeSource2D& s = sources_[cell_items_[k]];
        best = std::min(best, s.size + grading_ * point_segment_distance(x, s.a, s.b));
      }
    };
    for (int r = 0; r <= max_ring; ++r) {
      // Every cell of ring r is at least (r - 1) cells away from x.
      if (min_source_size_ + grading_ * std::max(0, r - 1) * cell_ >= best)
        break;
      if (r == 0) {
        visit(ci, cj);
        continue;
      }
      for (int d = -r; d <= r; ++d) {
        visit(ci + d, cj - r);
        visit(ci + d, cj + r);
      }
      for (int d = -r + 1; d <= r - 1; ++d) {
        visit(ci - r, cj + d);
        visit(ci + r, cj + d);
      }
    }
  }
  return std::max(floor_, best);
}

} // namespace magfem
