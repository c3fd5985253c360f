#pragma once
// Cutting a large 3D domain in two along a closed surface of its geometry, so that TetGen can
// mesh the two pieces at once (issue 35: on benchmark32 TetGen's refinement was the largest
// single-threaded stage while the second core idled).
//
// The cut is a whole sphere of frame 0 (the spherical grid about the origin that holds the
// domain ball) made only of interface faces: the magnets' outer sphere of a spherical
// actuator, the inner sphere of the open boundary's shell. Its triangles are in the surface
// mesh already, and TetGen's -Y keeps them, so both pieces' volume meshes have exactly these
// triangles on the cut and conform without any new point on it. Piece 0 is the inside
// (r <= R), piece 1 the outside; each gets the cut's triangles.
//
// No split (and the mesh is the single TetGen call's, bit for bit) when the estimate is below
// MeshOptions3D::split_min_tetrahedra, when no such sphere exists (boxes, cylinders, STL parts
// in the air around the origin...), with symmetry planes, when a surface triangle crosses the
// sphere (a part of another frame across it), or when the better balanced cut leaves the
// smaller piece under split_min_share of the work. The choice depends on the case only, never
// on the thread count.
#include <array>
#include <optional>
#include <vector>

#include "mesh/grid_frame3d.hpp"
#include "mesh/mesh_estimate3d.hpp"
#include "mesh/surface_mesher3d.hpp"

namespace magfem {

// The smaller piece's share of the estimated tetrahedra below which a split is not worth it
// (the pieces run at once: the time is the larger piece's).
inline constexpr double split_min_share = 0.2;

// Radii (metres) of the spheres a split may use: breakpoints of frame 0's radial axis whose
// grid faces cover the whole sphere, with the domain on both sides. Empty with symmetry planes.
std::vector<double> split_sphere_radii(const Geometry3D& geometry, const GridDecomposition3D& dec);

// Of `radii`, the one that divides the estimate (computed with within_radii = radii) most
// evenly; nullopt when the estimate is below min_tetrahedra or the smaller piece's share is
// below split_min_share.
std::optional<double> choose_split_radius(const std::vector<double>& radii,
                                          const MeshEstimate3D& estimate, double min_tetrahedra);

struct DomainSplit3D {
  double radius = 0;    // the cut: the sphere of this radius about the origin
  int radial_break = 0; // its index in frame 0's radial breakpoints
  // Piece 0 inside the sphere, piece 1 outside; each piece's surface mesh (triangles in the
  // whole mesh's order) and, per point of it, the point's index in the whole surface mesh.
  std::array<SurfaceMesh3D, 2> pieces;
  std::array<std::vector<int>, 2> whole_point;

  // Whether grid face `face` is a triangle set of the cut.
  bool on_cut(const GridDecomposition3D& dec, int face) const;
  // The piece holding the point (off the cut).
  int piece_of(const Vec3& x) const { return x.norm() < radius ? 0 : 1; }
};

// The two pieces of `surf` cut at the sphere of frame 0's radial breakpoint `radius`; nullopt
// when a triangle off the cut has points on both sides of it.
std::optional<DomainSplit3D> split_surface_mesh(const GridDecomposition3D& dec,
                                                const SurfaceMesh3D& surf, double radius);

} // namespace magfem
