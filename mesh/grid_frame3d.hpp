#pragma once
// Curvilinear grids that make shared faces conform by construction. Parts of one kind placed
// in one frame (spherical segments about one centre and orientation, coaxial cylinders, boxes
// of one orientation) are cut into the cells of a common grid whose breakpoints are all their
// bounds; a grid face whose two cells carry different labels is a surface of the domain and is
// triangulated exactly once, whichever parts it separates.
//
// Grid coordinates q: spherical (r, theta, phi), cylindrical (rho, alpha, z), cartesian
// (x, y, z), all in the frame's local coordinates (SI metres and radians). Axis 2 (phi) of a
// spherical and axis 1 (alpha) of a cylindrical grid are periodic.
#include <array>
#include <string>
#include <vector>

#include "mesh/geometry3d.hpp"
#include "mesh/mesh3d.hpp"

namespace magfem {

enum class GridKind3D { spherical, cylindrical, cartesian };

// Cell label beyond the domain (internal to the mesher; never appears in a Mesh3D).
inline constexpr int region_exterior_3d = -3;

struct GridFrame3D {
  GridKind3D kind = GridKind3D::cartesian;
  Placement placement;                       // grid coordinates live in this frame
  std::array<std::vector<double>, 3> breaks; // sorted breakpoints per axis
  std::array<bool, 3> periodic{false, false, false};
  int label_above = region_background_3d; // beyond the last breakpoint of axis 0
  std::vector<int> labels;                // per cell, see cell_index
  std::vector<int> parts;                 // Geometry3D part indices gridded here

  int n_cells(int axis) const;
  double lo(int axis, int i) const { return breaks[axis][i]; }
  double hi(int axis, int i) const; // upper bound of cell i (periodic wrap adds 2 pi)
  int cell_index(int i, int j, int k) const;
  // Label of cell (c[0], c[1], c[2]); indices outside a non-periodic axis give air, or
  // label_above beyond the last cell of axis 0.
  int label(std::array<int, 3> c) const;
  Vec3 local_point(const Vec3& q) const;
  Vec3 point(const Vec3& q) const { return placement.to_global(local_point(q)); }
  // Global unit vector in the direction of increasing q[axis] at q.
  Vec3 axis_direction(int axis, const Vec3& q) const;
};

// A grid face with different labels on its two sides: q[axis] = breaks[axis][index]; the
// other coordinates span cell cells[0] of axis (axis+1)%3 and cells[1] of axis (axis+2)%3.
struct GridFace3D {
  int frame = 0;
  int axis = 0;
  int index = 0;
  std::array<int, 2> cells{0, 0};
  int label_low = 0, label_high = 0; // labels below / above the face along axis

  int free_axis(int n) const { return (axis + 1 + n) % 3; }
};

struct GridDecomposition3D {
  std::vector<GridFrame3D> frames; // frames[0]: spherical, identity placement, holds the
                                   // outer ball (and shell) boundaries
  std::vector<GridFace3D> faces;
  std::vector<int> part_frame; // per part, its frame (-1: a TriangleSurface, in no grid)
};

// Validates every part (degenerate primitive, bad placement, part of frame 0 beyond the
// domain -> MeshError naming the part), groups parts into frames, labels the cells (two parts
// in one cell -> MeshError naming both) and lists the interface faces.
GridDecomposition3D decompose_geometry_3d(const Geometry3D& geometry);

// True when the global point x lies in the part enlarged by tol (metres).
bool part_contains(const Part3D& part, const Vec3& x, double tol);

} // namespace magfem
