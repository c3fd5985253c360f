#include "mesh/face_soup3d.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include <Eigen/Geometry>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "mesh/mesh_error.hpp"

namespace magfem {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Traits = CGAL::AABB_traits<K, Primitive>;
using Tree = CGAL::AABB_tree<Traits>;

// Hits at |cos(incidence)| below this are grazing (a ray running along a neighbouring face).
constexpr double grazing_cos = 0.2;

K::Point_3 cgal(const Vec3& x) {
  return {x.x(), x.y(), x.z()};
}

std::string label_name(const Geometry3D& geo, int label) {
  if (label >= 0)
    return geo.parts[label].name;
  return label == region_background_3d ? "air" : "the domain boundary";
}

} // namespace

struct FaceSoup3D::Tree {
  std::vector<Triangle> triangles;
  ::magfem::Tree tree;
};

FaceSoup3D::FaceSoup3D(const GridDecomposition3D& dec, const std::vector<double>& spacing)
    : dec_(dec), tree_(std::make_unique<Tree>()) {
  for (std::size_t f = 0; f < dec.faces.size(); ++f) {
    const GridFace3D& face = dec.faces[f];
    samples_.push_back(sample_face(dec.frames[face.frame], face, spacing[f]));
    const FaceSamples3D& s = samples_.back();
    auto p = [&](int i, int j) { return s.points[i * s.n2 + j]; };
    for (int i = 0; i + 1 < s.n1; ++i)
      for (int j = 0; j + 1 < s.n2; ++j) {
        const Vec3 a = p(i, j), b = p(i + 1, j), c = p(i + 1, j + 1), d = p(i, j + 1);
        for (const auto& t : {std::array<Vec3, 3>{a, b, c}, std::array<Vec3, 3>{a, c, d}}) {
          // Rows collapsing at a pole or an apex give degenerate triangles: skip them.
          if ((t[1] - t[0]).cross(t[2] - t[0]).norm() <= 1e-14 * (t[1] - t[0]).squaredNorm())
            continue;
          tree_->triangles.emplace_back(cgal(t[0]), cgal(t[1]), cgal(t[2]));
          tri_face_.push_back(static_cast<int>(f));
        }
      }
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
}

FaceSoup3D::~FaceSoup3D() = default;

void FaceSoup3D::check_parts(const Geometry3D& geo) const {
  const auto& tris = tree_->triangles;
  const double r1 = geo.outer.radius;
  const double tol = 1e-9 * r1;
  // Bounding boxes of the parts (from their face samples) and a witness point on each.
  std::vector<Eigen::AlignedBox3d> box(geo.parts.size());
  std::vector<Vec3> witness(geo.parts.size(), Vec3::Constant(std::nan("")));
  for (std::size_t f = 0; f < dec_.faces.size(); ++f) {
    const GridFace3D& face = dec_.faces[f];
    for (int label : {face.label_low, face.label_high}) {
      if (label < 0)
        continue;
      if (std::isnan(witness[label].x()))
        witness[label] = samples_[f].points[0];
      for (const Vec3& x : samples_[f].points) {
        box[label].extend(x);
        // Frame-0 parts are bounded by the grid; others must stay strictly inside the ball.
        if (face.frame != 0 && x.norm() >= r1 - tol)
          throw MeshError(geo.parts[label].name, "",
                          "extends beyond the domain ball of radius " + std::to_string(r1) + " m");
      }
    }
  }
  for (auto& b : box)
    b.extend(b.min() - Vec3::Constant(tol)).extend(b.max() + Vec3::Constant(tol));
  // Parts whose boxes overlap a part of another frame: test their faces' triangles.
  std::vector<bool> suspect(geo.parts.size(), false);
  for (std::size_t p = 0; p < geo.parts.size(); ++p)
    for (std::size_t q = p + 1; q < geo.parts.size(); ++q) {
      if (dec_.part_frame[p] == dec_.part_frame[q])
        continue;
      Eigen::AlignedBox3d bp = box[p];
      bp.extend(bp.min() - Vec3::Constant(tol)).extend(bp.max() + Vec3::Constant(tol));
      if (!bp.intersects(box[q]))
        continue;
      suspect[p] = suspect[q] = true;
      if (part_contains(geo.parts[q], witness[p], -tol))
        throw MeshError(geo.parts[p].name, "", "lies inside part '" + geo.parts[q].name + "'");
      if (part_contains(geo.parts[p], witness[q], -tol))
        throw MeshError(geo.parts[q].name, "", "lies inside part '" + geo.parts[p].name + "'");
    }
  // Triangles of each suspect part, tested pairwise against a tree of the other part's.
  std::vector<std::vector<Triangle>> part_tris(geo.parts.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const GridFace3D& face = dec_.faces[tri_face_[t]];
    for (int label : {face.label_low, face.label_high})
      if (label >= 0 && suspect[label])
        part_tris[label].push_back(tris[t]);
  }
  for (std::size_t q = 0; q < geo.parts.size(); ++q) {
    if (!suspect[q])
      continue;
    const ::magfem::Tree tree_q(part_tris[q].begin(), part_tris[q].end());
    for (std::size_t p = 0; p < geo.parts.size(); ++p) {
      if (p == q || dec_.part_frame[p] == dec_.part_frame[q] || !suspect[p])
        continue;
      if (!box[p].intersects(box[q]))
        continue;
      for (const Triangle& t : part_tris[p])
        if (tree_q.do_intersect(t))
          throw MeshError(geo.parts[p].name, "",
                          "intersects or touches part '" + label_name(geo, static_cast<int>(q)) +
                              "' (parts of different frames must be disjoint)");
    }
  }
}

std::vector<int> FaceSoup3D::labels_met(const std::array<Vec3, 3>& triangle) const {
  std::vector<Iterator> hits;
  tree_->tree.all_intersected_primitives(
      Triangle(cgal(triangle[0]), cgal(triangle[1]), cgal(triangle[2])), std::back_inserter(hits));
  std::vector<int> labels;
  for (Iterator id : hits) {
    const GridFace3D& face = dec_.faces[tri_face_[id - tree_->triangles.begin()]];
    labels.push_back(face.label_low);
    labels.push_back(face.label_high);
  }
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  return labels;
}

double FaceSoup3D::distance_to_face(const Vec3& origin, const Vec3& direction, double min_distance,
                                    int* hit_face, bool parts_only) const {
  const K::Ray_3 ray(cgal(origin), K::Vector_3(direction.x(), direction.y(), direction.z()));
  const auto& tris = tree_->triangles;
  const double tol = 1e-9 * dec_.frames[0].breaks[0].back();
  auto skip = [&](Iterator id) {
    const GridFace3D& face = dec_.faces[tri_face_[id - tris.begin()]];
    if (parts_only && face.label_low < 0 && face.label_high < 0)
      return true;
    const Vec3 a(id->vertex(0).x(), id->vertex(0).y(), id->vertex(0).z());
    const Vec3 b(id->vertex(1).x(), id->vertex(1).y(), id->vertex(1).z());
    const Vec3 c(id->vertex(2).x(), id->vertex(2).y(), id->vertex(2).z());
    const Vec3 n = (b - a).cross(c - a);
    const double dn = n.dot(direction);
    if (std::abs(dn) < grazing_cos * n.norm())
      return true;
    if ((a - origin).dot(n) / dn < min_distance)
      return true; // plane hit too close
    return face_contains(dec_.frames[face.frame], face, origin, tol);
  };
  const auto hit = tree_->tree.first_intersection(ray, skip);
  if (hit_face)
    *hit_face = -1;
  if (!hit)
    return std::numeric_limits<double>::infinity();
  if (const K::Point_3* p = boost::get<K::Point_3>(&hit->first)) {
    if (hit_face)
      *hit_face = tri_face_[hit->second - tris.begin()];
    return std::sqrt(CGAL::squared_distance(*p, ray.source()));
  }
  return std::numeric_limits<double>::infinity(); // a segment: only grazing hits do that
}

} // namespace magfem
