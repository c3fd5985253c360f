#include "mesh/surface_part_rays3d.hpp"

#include <cmath>
#include <limits>

#include "mesh/grid_frame3d.hpp"
#include "mesh/triangle_tree3d.hpp"

namespace magfem {
namespace {
using namespace triangle_tree;
using AabbTree = triangle_tree::Tree;

// As in FaceSoup3D: hits at |cos(incidence)| below this run along a face.
constexpr double grazing_cos = 0.2;

} // namespace

struct SurfacePartRays3D::Tree {
  std::vector<Triangle> triangles;
  std::vector<int> part;
  AabbTree tree;
};

SurfacePartRays3D::SurfacePartRays3D(const Geometry3D& geo, const GridDecomposition3D& dec,
                                     const FaceSoup3D& soup)
    : geo_(geo), dec_(dec), soup_(soup), tree_(std::make_unique<Tree>()) {
  for (std::size_t p = 0; p < geo.parts.size(); ++p) {
    const auto* s = std::get_if<TriangleSurface>(&geo.parts[p].shape);
    if (!s || geo.parts[p].air)
      continue;
    const Placement& place = geo.parts[p].placement;
    for (const auto& t : s->triangles) {
      tree_->triangles.emplace_back(cgal(place.to_global(s->points[t[0]])),
                                    cgal(place.to_global(s->points[t[1]])),
                                    cgal(place.to_global(s->points[t[2]])));
      tree_->part.push_back(static_cast<int>(p));
    }
  }
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
}

SurfacePartRays3D::~SurfacePartRays3D() = default;

double SurfacePartRays3D::gap(int self, const Vec3& origin, const Vec3& direction,
                              double min_distance) const {
  double best = std::numeric_limits<double>::infinity();
  int face = -1;
  const double w = soup_.distance_to_face(origin, direction, min_distance, &face, true);
  if (face >= 0) {
    // A face of a built-in part (parts_only): that of an air part bounds no gap.
    const GridFace3D& f = dec_.faces[static_cast<std::size_t>(face)];
    const int part = f.label_low == region_background_3d ? f.label_high : f.label_low;
    if (part < 0 || !geo_.parts[static_cast<std::size_t>(part)].air)
      best = w;
  }
  if (tree_->triangles.empty())
    return best;
  const K::Ray_3 ray(cgal(origin), K::Vector_3(direction.x(), direction.y(), direction.z()));
  auto skip = [&](Iterator id) {
    if (tree_->part[id - tree_->triangles.begin()] == self)
      return true;
    const Vec3 a = vec(id->vertex(0)), b = vec(id->vertex(1)), c = vec(id->vertex(2));
    const Vec3 n = (b - a).cross(c - a);
    const double dn = n.dot(direction);
    return std::abs(dn) < grazing_cos * n.norm() || (a - origin).dot(n) / dn < min_distance;
  };
  const auto hit = tree_->tree.first_intersection(ray, skip);
  if (hit)
    if (const K::Point_3* p = boost::get<K::Point_3>(&hit->first))
      best = std::min(best, (vec(*p) - origin).norm());
  return best;
}

} // namespace magfem
