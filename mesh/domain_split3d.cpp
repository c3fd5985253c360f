#include "mesh/domain_split3d.hpp"

#include <algorithm>
#include <cmath>

namespace magfem {

namespace {

// Points within this fraction of the radius of the cut lie on it (its triangles' points are
// on the sphere to rounding).
constexpr double on_sphere_tol = 1e-9;

int radial_break_of(const GridFrame3D& f, double radius) {
  const auto& b = f.breaks[0];
  for (std::size_t i = 0; i < b.size(); ++i)
    if (b[i] == radius)
      return static_cast<int>(i);
  return -1;
}

// Which piece a triangle off the cut belongs to (-1: both sides, it crosses the sphere).
int piece_of_triangle(const SurfaceMesh3D& surf, const std::array<int, 3>& tri, double radius) {
  double r_min = radius * 10, r_max = 0;
  for (int v : tri) {
    const double r = surf.points[static_cast<std::size_t>(v)].norm();
    r_min = std::min(r_min, r);
    r_max = std::max(r_max, r);
  }
  const double tol = on_sphere_tol * radius;
  if (r_max <= radius + tol && r_min < radius - tol)
    return 0;
  if (r_min >= radius - tol && r_max > radius + tol)
    return 1;
  return -1; // across the sphere, or on it without being one of the cut's faces
}

} // namespace

std::vector<double> split_sphere_radii(const Geometry3D& geo, const GridDecomposition3D& dec) {
  if (!geo.symmetry.empty() || dec.frames.empty())
    return {};
  const GridFrame3D& f = dec.frames[0];
  const int n_sphere_cells = f.n_cells(1) * f.n_cells(2);
  std::vector<int> n_faces(f.breaks[0].size(), 0);
  std::vector<bool> bounds_domain(f.breaks[0].size(), false);
  for (const GridFace3D& face : dec.faces) {
    if (face.frame != 0 || face.axis != 0)
      continue;
    ++n_faces[static_cast<std::size_t>(face.index)];
    if (face.label_low == region_exterior_3d || face.label_high == region_exterior_3d)
      bounds_domain[static_cast<std::size_t>(face.index)] = true;
  }
  std::vector<double> radii;
  for (std::size_t i = 0; i < n_faces.size(); ++i)
    if (n_faces[i] == n_sphere_cells && !bounds_domain[i] && f.breaks[0][i] > 0)
      radii.push_back(f.breaks[0][i]);
  return radii;
}

std::optional<double> choose_split_radius(const std::vector<double>& radii,
                                          const MeshEstimate3D& estimate, double min_tetrahedra) {
  const double total = estimate.tetrahedra;
  if (radii.empty() || !(total >= min_tetrahedra) ||
      estimate.tetrahedra_within.size() != radii.size())
    return std::nullopt;
  std::size_t best = 0;
  for (std::size_t i = 1; i < radii.size(); ++i)
    if (std::abs(estimate.tetrahedra_within[i] - total / 2) <
        std::abs(estimate.tetrahedra_within[best] - total / 2))
      best = i;
  const double inside = estimate.tetrahedra_within[best];
  if (std::min(inside, total - inside) < split_min_share * total)
    return std::nullopt;
  return radii[best];
}

bool DomainSplit3D::on_cut(const GridDecomposition3D& dec, int face) const {
  if (face < 0)
    return false;
  const GridFace3D& f = dec.faces[static_cast<std::size_t>(face)];
  return f.frame == 0 && f.axis == 0 && f.index == radial_break;
}

std::optional<DomainSplit3D> split_surface_mesh(const GridDecomposition3D& dec,
                                                const SurfaceMesh3D& surf, double radius) {
  DomainSplit3D split;
  split.radius = radius;
  split.radial_break = radial_break_of(dec.frames[0], radius);
  if (split.radial_break < 0)
    return std::nullopt;
  std::array<std::vector<int>, 2> piece_point; // whole point -> piece point (-1: not in it)
  for (auto& p : piece_point)
    p.assign(surf.points.size(), -1);
  auto add = [&](int piece, std::size_t t) {
    SurfaceMesh3D& s = split.pieces[static_cast<std::size_t>(piece)];
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const int v = surf.triangles[t][static_cast<std::size_t>(k)];
      int& local = piece_point[static_cast<std::size_t>(piece)][static_cast<std::size_t>(v)];
      if (local < 0) {
        local = static_cast<int>(s.points.size());
        s.points.push_back(surf.points[static_cast<std::size_t>(v)]);
        split.whole_point[static_cast<std::size_t>(piece)].push_back(v);
      }
      tri[static_cast<std::size_t>(k)] = local;
    }
    s.triangles.push_back(tri);
    s.triangle_face.push_back(surf.triangle_face[t]);
  };
  for (std::size_t t = 0; t < surf.triangles.size(); ++t) {
    if (split.on_cut(dec, surf.triangle_face[t])) {
      add(0, t);
      add(1, t);
      continue;
    }
    const int piece = piece_of_triangle(surf, surf.triangles[t], radius);
    if (piece < 0)
      return std::nullopt;
    add(piece, t);
  }
  // A point on no triangle (TetGen keeps such an input point as a vertex of the volume mesh)
  // goes to the piece it lies in, so that it is a vertex of the stitched mesh too.
  for (std::size_t v = 0; v < surf.points.size(); ++v) {
    if (piece_point[0][v] >= 0 || piece_point[1][v] >= 0)
      continue;
    const auto piece = static_cast<std::size_t>(split.piece_of(surf.points[v]));
    piece_point[piece][v] = static_cast<int>(split.pieces[piece].points.size());
    split.pieces[piece].points.push_back(surf.points[v]);
    split.whole_point[piece].push_back(static_cast<int>(v));
  }
  return split;
}

} // namespace magfem
