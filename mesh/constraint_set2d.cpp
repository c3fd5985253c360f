#include "mesh/constraint_set2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

namespace magfem {

namespace {

constexpr int max_cells_per_axis = 1024;

std::uint64_t cell_key(std::int64_t i, std::int64_t j) {
  return (std::uint64_t(i) << 32) ^ std::uint64_t(std::uint32_t(j));
}

std::uint64_t edge_key(int a, int b) {
  return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

// Points with merging of near-duplicates through a hash grid of cell size `merge`.
class PointPool {
public:
  explicit PointPool(double merge) : merge_(merge) {}

  int add(const Vec2& p, std::vector<Vec2>& points) {
    const std::int64_t i = std::int64_t(std::floor(p.x() / merge_));
    const std::int64_t j = std::int64_t(std::floor(p.y() / merge_));
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        const auto range = grid_.equal_range(cell_key(i + di, j + dj));
        for (auto it = range.first; it != range.second; ++it)
          if ((points[std::size_t(it->second)] - p).norm() <= merge_)
            return it->second;
      }
    points.push_back(p);
    grid_.emplace(cell_key(i, j), int(points.size() - 1));
    return int(points.size() - 1);
  }

private:
  double merge_;
  std::unordered_multimap<std::uint64_t, int> grid_;
};

double point_segment_distance(const Vec2& x, const Vec2& a, const Vec2& b, double& t) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  t = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

// Splits every segment at the vertices lying within `merge` of it.
void split_at_close_vertices(ConstraintSet2D& c, double merge) {
  if (c.segments.empty())
    return;
  Vec2 lo = c.points.front(), hi = lo;
  std::vector<double> lengths;
  for (const Vec2& p : c.points)
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (const auto& s : c.segments)
    lengths.push_back((c.points[s[1]] - c.points[s[0]]).norm());
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const double cell = std::max(lengths[lengths.size() / 2], extent / max_cells_per_axis);
  const int n = std::clamp(int(std::ceil(extent / cell)) + 1, 1, max_cells_per_axis + 1);
  const auto index = [&](double v, double o) {
    return std::clamp(int(std::floor((v - o) / cell)), 0, n - 1);
  };
  std::vector<std::vector<int>> cells(std::size_t(n) * n);
  for (int k = 0; k < int(c.segments.size()); ++k) {
    const Vec2 &a = c.points[c.segments[k][0]], &b = c.points[c.segments[k][1]];
    for (int j = index(std::min(a.y(), b.y()) - merge, lo.y());
         j <= index(std::max(a.y(), b.y()) + merge, lo.y()); ++j)
      for (int i = index(std::min(a.x(), b.x()) - merge, lo.x());
           i <= index(std::max(a.x(), b.x()) + merge, lo.x()); ++i)
        cells[std::size_t(j) * n + i].push_back(k);
  }
  std::vector<std::vector<std::pair<double, int>>> splits(c.segments.size());
  for (int p = 0; p < int(c.points.size()); ++p) {
    const Vec2& x = c.points[p];
    for (int k : cells[std::size_t(index(x.y(), lo.y())) * n + index(x.x(), lo.x())]) {
      const auto& s = c.segments[k];
      if (s[0] == p || s[1] == p)
        continue;
      double t = 0;
      if (point_segment_distance(x, c.points[s[0]], c.points[s[1]], t) <= merge && t > 0 && t < 1)
        splits[k].emplace_back(t, p);
    }
  }
  std::vector<std::array<int, 2>> out;
  std::unordered_set<std::uint64_t> seen;
  const auto emit = [&](int a, int b) {
    if (a != b && seen.insert(edge_key(a, b)).second)
      out.push_back({a, b});
  };
  for (std::size_t k = 0; k < c.segments.size(); ++k) {
    auto& sp = splits[k];
    std::sort(sp.begin(), sp.end());
    int prev = c.segments[k][0];
    for (const auto& [t, p] : sp) {
      emit(prev, p);
      prev = p;
    }
    emit(prev, c.segments[k][1]);
  }
  c.segments = std::move(out);
}

} // namespace

ConstraintSet2D build_constraint_set(const std::vector<std::vector<Vec2>>& loops, double merge) {
  ConstraintSet2D c;
  PointPool pool(merge);
  std::unordered_set<std::uint64_t> seen;
  for (const auto& loop : loops) {
    std::vector<int> ids;
    for (const Vec2& p : loop)
      ids.push_back(pool.add(p, c.points));
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const int a = ids[i], b = ids[(i + 1) % ids.size()];
      if (a != b && seen.insert(edge_key(a, b)).second)
        c.segments.push_back({a, b});
    }
  }
  split_at_close_vertices(c, merge);
  return c;
}

} // namespace magfem
