#pragma once
// 2D planar geometry as the mesher sees it: parts built from primitives, in SI metres and
// radians (the case reader converts units once). Parts may overlap earlier ones only when
// they say so (replace_earlier); where they do, the later part wins. Whatever is not covered
// by a part is background air.
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>

#include "mesh/symmetry_plane2d.hpp"

namespace magfem {

using Vec2 = Eigen::Vector2d;

struct Disk {
  Vec2 center = Vec2::Zero();
  double radius = 0;
};
struct Annulus {
  Vec2 center = Vec2::Zero();
  double r_inner = 0, r_outer = 0;
};
// Angles counter-clockwise from +x; r_inner = 0 gives a pie slice.
struct AnnularSector {
  Vec2 center = Vec2::Zero();
  double r_inner = 0, r_outer = 0;
  double angle_start = 0, angle_end = 0;
};
// Axis-aligned before rotation (radians, counter-clockwise about the centre).
struct Rectangle {
  Vec2 center = Vec2::Zero();
  double width = 0, height = 0;
  double rotation = 0;
};
// Simple polygon, vertices in order (either orientation).
struct Polygon {
  std::vector<Vec2> vertices;
};

using Shape2D = std::variant<Disk, Annulus, AnnularSector, Rectangle, Polygon>;

struct Part2D {
  std::string name;
  Shape2D shape;
  double max_size = 0; // metres; 0 = use MeshOptions2D::default_size
  // May cover earlier parts (which lose that area); otherwise sharing area with an earlier
  // part is a MeshError (see region_overlap2d.hpp).
  bool replace_earlier = false;
};

enum class OuterKind { open, dirichlet, neumann };

// The computational domain is the disk of `radius` about the origin. For `open`, an annular
// shell from radius to shell_ratio * radius is added and mapped to infinity by the solver
// (shell transformation), so the domain disk may be tight around the device.
struct OuterBoundary2D {
  OuterKind kind = OuterKind::open;
  double radius = 0;
  double shell_ratio = 1.5;
};

struct MeshOptions2D {
  double default_size = 0;       // metres, for background air (and parts without max_size)
  double chord_tolerance = 0;    // metres: max distance between an arc and its chords
  double min_angle_deg = 28.0;   // CGAL quality bound (guaranteed up to ~20.7 deg)
  int gap_layers = 3;            // minimum element layers across every thin air gap
  double size_scale = 1.0;       // multiplies every size (uniform refinement studies)
};

// Planar: the xy-plane (A_z). Axisymmetric: the r-z half plane x = r >= 0, y = z, standing for
// a body of revolution about the y axis; the domain and shell are then half disks whose
// straight side is the axis.
enum class Symmetry2D { planar, axisymmetric };

struct Geometry2D {
  Symmetry2D symmetry = Symmetry2D::planar;
  // Symmetry planes (mesh/symmetry_plane2d.hpp): only the side where each plane's coordinate
  // is >= 0 is meshed (parts are cut there); the cut is a boundary of the mesh.
  std::vector<SymmetryPlane2D> planes;
  std::vector<Part2D> parts;
  OuterBoundary2D outer;
  MeshOptions2D options;
};

} // namespace magfem
