#pragma once
// Flux of B through a line section of a planar or axisymmetric solution (section_spec.hpp,
// Kind::line), integrated from the element field (Field2D::B, never a recovered value) over
// the exact pieces of the line inside every triangle.
//
// Each straight triangle clips the segment to a piece; 4-point Gauss-Legendre on the piece
// reads B at the piece's barycentric coordinates. B is a polynomial of degree order - 1 on a
// straight triangle (linear materials, uniform magnetization), so B.n (times r when
// axisymmetric) is integrated exactly: the flux then equals the potential's difference between
// the ends, A(start) - A(end) (planar, per metre) or 2 pi (r A)(end) - 2 pi (r A)(start)
// (axisymmetric), to round-off (tested). |B| is integrated to the rule's degree 7. A line along
// mesh edges is counted once, by the triangles on its +n side.
//
// Planar results are for `depth` metres of depth (1, or the case's stack length), as energy
// and forces; axisymmetric ones for the whole surface of revolution (area 2 pi r ds).
#include <map>

#include "postproc/field2d.hpp"
#include "postproc/section_flux3d.hpp"
#include "postproc/section_spec.hpp"

namespace magfem {

SectionFlux integrate_section_2d(const Field2D& field, const SectionSpec& section, double depth);

// Fills out.parts (ascending region) and out.total from per-region sums, and
// out.outside_area_m2 from out.nominal_area_m2 (also for sections read in pieces).
void finish_section_2d(SectionFlux& out, const std::map<int, SectionPart>& parts);

} // namespace magfem
