#include "mesh/surface_index3d.hpp"

#include <cmath>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

namespace magfem {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<K::Point_3>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<SurfaceMesh, K>;
} // namespace

struct SurfaceIndex3D::Impl {
  SurfaceMesh mesh;
  Tree tree;
  std::unique_ptr<Side> side;
};

SurfaceIndex3D::SurfaceIndex3D(const std::vector<Vec3>& points,
                               const std::vector<std::array<int, 3>>& triangles)
    : impl_(std::make_unique<Impl>()) {
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(points.size());
  for (const Vec3& x : points)
    v.push_back(impl_->mesh.add_vertex(K::Point_3(x.x(), x.y(), x.z())));
  for (const auto& t : triangles)
    impl_->mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  impl_->tree.insert(faces(impl_->mesh).first, faces(impl_->mesh).second, impl_->mesh);
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
  // Side_of_triangle_mesh given a built tree does not build (nor lazily rebuild) its own.
  impl_->side = std::make_unique<Side>(impl_->tree);
}

SurfaceIndex3D::~SurfaceIndex3D() = default;

bool SurfaceIndex3D::contains(const Vec3& x, double tol) const {
  const K::Point_3 p(x.x(), x.y(), x.z());
  const CGAL::Bounded_side s = (*impl_->side)(p);
  if (s == CGAL::ON_BOUNDARY)
    return tol >= 0;
  const bool inside = s == CGAL::ON_BOUNDED_SIDE;
  if (tol == 0)
    return inside;
  const double d = distance(x);
  return tol > 0 ? (inside || d <= tol) : (inside && d >= -tol);
}

double SurfaceIndex3D::distance(const Vec3& x) const {
  return std::sqrt(impl_->tree.squared_distance(K::Point_3(x.x(), x.y(), x.z())));
}

} // namespace magfem
