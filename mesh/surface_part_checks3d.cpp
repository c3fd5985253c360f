#include "mesh/surface_part_checks3d.hpp"

#include <cstdio>

#include "mesh/grid_frame3d.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/part_overlap3d.hpp"
#include "mesh/triangle_tree3d.hpp"

namespace magfem {
namespace {
using namespace triangle_tree;

std::vector<std::array<Vec3, 3>> global_triangles(const Part3D& part, const TriangleSurface& s) {
  std::vector<std::array<Vec3, 3>> out;
  for (const auto& t : s.triangles)
    out.push_back({part.placement.to_global(s.points[t[0]]),
                   part.placement.to_global(s.points[t[1]]),
                   part.placement.to_global(s.points[t[2]])});
  return out;
}

std::string who(const TriangleSurface& s) {
  return "the surface of " + s.file;
}

[[noreturn]] void overlap(const Part3D& part, const TriangleSurface& s, const Part3D& other,
                          const std::string& how) {
  throw MeshError(part.name, "file",
                  who(s) + " " + how + " part '" + other.name +
                      "' (a CAD part must keep clear of every other part)");
}

void check_inside_ball(const Geometry3D& geo, const Part3D& part, const TriangleSurface& s) {
  const double r1 = geo.outer.radius;
  for (const Vec3& local : s.points) {
    const Vec3 x = part.placement.to_global(local);
    if (x.norm() >= r1 * (1 - 1e-9)) {
      char text[200];
      std::snprintf(text, sizeof text,
                    " reaches %.6g mm from the origin, beyond the domain ball of radius %.6g mm",
                    x.norm() * 1e3, r1 * 1e3);
      throw MeshError(part.name, "file", who(s) + text);
    }
  }
}

// Against two surfaces: any triangle pair meeting, or one surface inside the other.
void check_pair(const Part3D& a, const TriangleSurface& sa, const Part3D& b,
                const TriangleSurface& sb) {
  std::vector<Triangle> tb;
  for (const auto& t : global_triangles(b, sb))
    tb.emplace_back(cgal(t[0]), cgal(t[1]), cgal(t[2]));
  const Tree tree(tb.begin(), tb.end());
  for (const auto& t : global_triangles(a, sa))
    if (tree.do_intersect(Triangle(cgal(t[0]), cgal(t[1]), cgal(t[2]))))
      overlap(a, sa, b, "intersects or touches");
  if (part_contains(b, a.placement.to_global(sa.points[0]), 0))
    overlap(a, sa, b, "lies inside");
  if (part_contains(a, b.placement.to_global(sb.points[0]), 0))
    overlap(a, sa, b, "contains");
}

} // namespace

void check_surface_parts(const Geometry3D& geo, const FaceSoup3D& soup) {
  const double tol = 1e-9 * geo.outer.radius;
  for (std::size_t p = 0; p < geo.parts.size(); ++p) {
    const Part3D& part = geo.parts[p];
    const auto* s = std::get_if<TriangleSurface>(&part.shape);
    if (!s)
      continue;
    check_inside_ball(geo, part, *s);
    // Built-in parts: their faces' coarse triangles against ours, then the volumes (a part
    // wholly inside the other meets no face).
    for (const auto& t : global_triangles(part, *s))
      for (int label : soup.labels_met(t))
        if (label >= 0)
          overlap(part, *s, geo.parts[label], "intersects or touches");
    for (std::size_t q = 0; q < geo.parts.size(); ++q) {
      if (q == p)
        continue;
      const Part3D& other = geo.parts[q];
      if (const auto* so = std::get_if<TriangleSurface>(&other.shape)) {
        if (q > p)
          check_pair(part, *s, other, *so);
        continue;
      }
      if (part_contains(other, part.placement.to_global(s->points[0]), -tol))
        overlap(part, *s, other, "lies inside");
      if (overlap_point(other, part))
        overlap(part, *s, other, "contains or overlaps");
    }
  }
}

} // namespace magfem
