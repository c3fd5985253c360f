#include "mesh/gap_rule2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace magfem {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr int max_cells_per_axis = 1024;
constexpr double facing_cos = -0.5; // normals at more than 120 degrees face each other
constexpr int first_round_samples = 3;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Uniform grid of segments answering "first segment hit by a ray" by walking the cells the ray
// crosses (Amanatides-Woo) and stopping at the first cell that contains a hit.
class SegmentGrid {
public:
  explicit SegmentGrid(const std::vector<AirBoundary2D>& edges) : edges_(edges) {
    lo_ = hi_ = edges.front().a;
    std::vector<double> lengths;
    for (const auto& e : edges) {
      lo_ = lo_.cwiseMin(e.a).cwiseMin(e.b);
      hi_ = hi_.cwiseMax(e.a).cwiseMax(e.b);
      lengths.push_back((e.b - e.a).norm());
    }
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const Vec2 extent = (hi_ - lo_).cwiseMax(Vec2::Constant(1e-300));
    cell_ = std::max(lengths[lengths.size() / 2], extent.maxCoeff() / max_cells_per_axis);
    nx_ = std::clamp(int(std::ceil(extent.x() / cell_)), 1, max_cells_per_axis);
    ny_ = std::clamp(int(std::ceil(extent.y() / cell_)), 1, max_cells_per_axis);
    cells_.resize(std::size_t(nx_) * ny_);
    for (int k = 0; k < int(edges.size()); ++k) {
      const auto& e = edges[k];
      const int i0 = index(std::min(e.a.x(), e.b.x()), lo_.x(), nx_);
      const int i1 = index(std::max(e.a.x(), e.b.x()), lo_.x(), nx_);
      const int j0 = index(std::min(e.a.y(), e.b.y()), lo_.y(), ny_);
      const int j1 = index(std::max(e.a.y(), e.b.y()), lo_.y(), ny_);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
          cells_[std::size_t(j) * nx_ + i].push_back(k);
    }
  }

  // Index of the first segment (other than `skip`) hit by o + t d, 0 < t <= t_max, or -1.
  int first_hit(const Vec2& o, const Vec2& d, double t_max, int skip, double& t_hit) const {
    int i = index(o.x(), lo_.x(), nx_), j = index(o.y(), lo_.y(), ny_);
    const int si = d.x() > 0 ? 1 : -1, sj = d.y() > 0 ? 1 : -1;
    const double dti = d.x() != 0 ? cell_ / std::abs(d.x()) : inf;
    const double dtj = d.y() != 0 ? cell_ / std::abs(d.y()) : inf;
    double ti = d.x() != 0 ? (lo_.x() + (i + (si > 0)) * cell_ - o.x()) / d.x() : inf;
    double tj = d.y() != 0 ? (lo_.y() + (j + (sj > 0)) * cell_ - o.y()) / d.y() : inf;
    int best = -1;
    t_hit = t_max;
    while (true) {
      for (int k : cells_[std::size_t(j) * nx_ + i]) {
        if (k == skip)
          continue;
        const double t = hit(o, d, edges_[k]);
        if (t <= t_hit) {
          t_hit = t;
          best = k;
        }
      }
      const double t_exit = std::min(ti, tj);
      if (t_exit >= t_hit)
        return best;
      if (ti < tj) {
        i += si;
        ti += dti;
      } else {
        j += sj;
        tj += dtj;
      }
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_)
        return best;
    }
  }

private:
  int index(double v, double origin, int n) const {
    return std::clamp(int(std::floor((v - origin) / cell_)), 0, n - 1);
  }

  // Ray parameter of the crossing with segment e, +inf when there is none.
  static double hit(const Vec2& o, const Vec2& d, const AirBoundary2D& e) {
    const Vec2 ab = e.b - e.a;
    const double denom = cross(d, ab);
    if (denom == 0)
      return inf;
    const Vec2 w = e.a - o;
    const double t = cross(w, ab) / denom, u = cross(w, d) / denom;
    return (u >= 0 && u <= 1 && t > 0) ? t : inf;
  }

  const std::vector<AirBoundary2D>& edges_;
  Vec2 lo_, hi_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

struct GapHit {
  Vec2 from, to;
  double size = inf; // h_gap, +inf when no gap
};

GapHit cast(const SegmentGrid& grid, const std::vector<AirBoundary2D>& edges, int k, double s,
            const GapRuleOptions& opt, double max_width) {
  const AirBoundary2D& e = edges[k];
  GapHit g{e.a + s * (e.b - e.a), {}, inf};
  double t = 0;
  const int h = grid.first_hit(g.from, e.normal, max_width, k, t);
  if (h < 0 || edges[h].owner == e.owner || e.normal.dot(edges[h].normal) > facing_cos)
    return g;
  if (t < opt.min_width)
    return g;
  g.to = g.from + t * e.normal;
  g.size = std::min(1.0, opt.size_scale) * t / opt.layers;
  return g;
}

} // namespace

std::vector<SizeSource2D> gap_sources(const std::vector<AirBoundary2D>& edges,
                                      const GapRuleOptions& opt) {
  std::vector<SizeSource2D> sources;
  if (edges.empty() || opt.layers < 1)
    return sources;
  const SegmentGrid grid(edges);
  // Gaps at least this wide already get `layers` elements of the air size.
  const double max_width = opt.layers * opt.air_size / std::min(1.0, opt.size_scale);
  const double shrink = 1.0 - 0.25 * opt.grading;
  for (int k = 0; k < int(edges.size()); ++k) {
    const double len = (edges[k].b - edges[k].a).norm();
    double h_min = inf;
    for (int m = 0; m < first_round_samples; ++m)
      h_min = std::min(h_min,
                       cast(grid, edges, k, (m + 0.5) / first_round_samples, opt, max_width).size);
    if (!(h_min < opt.air_size))
      continue;
    const int n = std::max(first_round_samples, int(std::ceil(len / (0.5 * h_min))));
    for (int m = 0; m < n; ++m) {
      const GapHit g = cast(grid, edges, k, (m + 0.5) / n, opt, max_width);
      if (g.size < opt.air_size)
        sources.push_back({g.from, g.to, g.size * shrink});
    }
  }
  return sources;
}

} // namespace magfem
