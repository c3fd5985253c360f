#pragma once
// CGAL's AABB tree over a vector of triangles, as the mesher's geometric queries use it
// (FaceSoup3D's coarse faces, the surface parts' checks and gap rays), and the conversions
// to and from our Vec3. Included only by .cpp files of mesh/ (CGAL stays inside mesh/).
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "mesh/placement3d.hpp"

namespace magfem::triangle_tree {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator>>>;

inline K::Point_3 cgal(const Vec3& x) {
  return {x.x(), x.y(), x.z()};
}
inline Vec3 vec(const K::Point_3& p) {
  return {p.x(), p.y(), p.z()};
}

} // namespace magfem::triangle_tree
