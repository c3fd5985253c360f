#include "mesh/adaptive_size2d.hpp"

#include <algorithm>
#include <limits>

namespace magfem {
namespace {
// As the mesher's own field (mesher2d.cpp): neighbouring sizes differ by about 1.5x at most.
constexpr double grading = 0.5;
} // namespace

SizeField2D adaptive_size_field(const Mesh2D& mesh, const std::vector<double>& target,
                                double floor) {
  std::vector<SizeSource2D> sources;
  sources.reserve(3 * mesh.n_triangles());
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Vec2& a = mesh.nodes[tri[k]];
      sources.push_back({a, mesh.nodes[tri[(k + 1) % 3]], target[t]});
      lo = lo.cwiseMin(a);
      hi = hi.cwiseMax(a);
    }
  }
  // Outside the old mesh (never queried in practice: the domain does not change) the nearest
  // sources decide; the region term adds nothing.
  const auto no_region_limit = [](const Vec2&) { return std::numeric_limits<double>::infinity(); };
  return SizeField2D(no_region_limit, std::move(sources), grading, floor, lo, hi);
}

std::vector<double> longest_edges(const Mesh2D& mesh) {
  std::vector<double> h(mesh.n_triangles());
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const auto& p = mesh.nodes;
    const auto& tri = mesh.triangles[t];
    h[t] = std::max({(p[tri[0]] - p[tri[1]]).norm(), (p[tri[1]] - p[tri[2]]).norm(),
                     (p[tri[2]] - p[tri[0]]).norm()});
  }
  return h;
}

} // namespace magfem
