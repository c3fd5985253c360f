#pragma once
// Flux of B through a plane section of the 3D domain (section_spec.hpp), integrated from the
// element field (Field3D::B, never a recovered nodal value) over the exact intersection of
// every tetrahedron with the plane.
//
// Method. Each straight (vertex) tetrahedron cut by the plane gives a convex triangle or
// quadrilateral; it is clipped to the section's outline in the plane's (u, v) coordinates,
// fan-triangulated, and integrated with the degree-4 Dunavant rule at the barycentric
// coordinates of each quadrature point in that tet. The element B is a polynomial of degree
// order - 1 on a straight tet (linear materials, uniform magnetization, no coils), so B.n and
// the area are integrated exactly; |B| (not a polynomial) and nonlinear, non-uniformly
// magnetized or coil-driven elements to the rule's degree 4. Each point of the plane is
// counted once: a vertex on the plane counts as on the +n side, so a section lying exactly on
// mesh faces reads the tets on its -n side.
//
// Disks are integrated over the regular 256-gon of the same area (circumradius
// r (2 pi / (N sin(2 pi / N)))^(1/2)): the area is pi r^2 to round-off, the polygon stays
// within 5.1e-5 r of the circle, and the two differ by 3.9e-5 pi r^2 (symmetric difference).
// Both are symmetric about the centre, so a field linear across the disk gives the same flux
// through either; a smooth field differs by far less than 1e-4 relative, and a material
// boundary along the rim by at most |jump of B.n| x 3.9e-5 pi r^2.
//
// Curved tets (order 2 next to spherical interfaces, DofMap3D::curve_to_spheres) are cut as
// their straight vertex tets and their field is read at the same barycentric coordinates,
// i.e. at the isoparametric image of the point, which lies off the plane by at most the chord
// gap. The section thus sees the faceted interface: the area it gives each region is that of
// the straight tets, differing from the true cross-section by the segments between chords and
// arcs (O(h^2 / R) per unit length of interface), and the flux by that area times the jump
// of B.n across the interface. Integrating over the curved cells exactly would need the
// curved tet's intersection with the plane (not a polygon); the per-region areas in the
// result let a user see the size of this effect.
#include <string>
#include <vector>

#include "postproc/field3d.hpp"
#include "postproc/section_spec.hpp"

namespace magfem {

// Integrals over the part of a section inside one region (a mesh tet_part: the case region's
// index, or region_background_3d for air outside every region). SI units.
struct SectionPart {
  int region = region_background_3d;
  double area_m2 = 0;
  double flux_Wb = 0;   // integral of B.n
  double abs_B_Tm2 = 0; // integral of |B|

  double Bn_avg_T() const { return area_m2 > 0 ? flux_Wb / area_m2 : 0; }
  double B_avg_T() const { return area_m2 > 0 ? abs_B_Tm2 / area_m2 : 0; }
};

struct SectionFlux {
  std::string name;
  double nominal_area_m2 = 0;     // SectionSpec::area()
  std::vector<SectionPart> parts; // one per region crossed, ascending region id
  SectionPart total;              // over all parts (region left at region_background_3d)
  // Area of the section outside the physical mesh (in the exterior shell or beyond the
  // faceted outer boundary): nominal - covered, clamped at 0. run_case_3d refuses > 0.
  double outside_area_m2 = 0;
};

SectionFlux integrate_section_3d(const Field3D& field, const SectionSpec& section);

} // namespace magfem
