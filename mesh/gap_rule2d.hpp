#pragma once
// The air-gap rule of the 2D mesher: at least `layers` element layers across every thin air gap.
//
// How a gap is detected. The input is every boundary segment between air (the background
// region) and something else, with its owner (the part on the other side, or the domain
// boundary) and its unit normal pointing into the air. From sample points on each segment a ray
// is cast along that normal through the air. Its first hit on another air boundary defines a
// gap of width d = hit distance when
//   - the hit segment has a different owner (two different parts, or a part and the domain
//     boundary: a slot inside one part is not a gap by this rule), and
//   - the two boundaries face each other: the angle between the normals exceeds 120 degrees
//     (so corners and junctions where boundaries merely meet are not gaps).
// Gaps narrower than min_width (the mesher passes 3 chord tolerances: each outline may be off
// by one, so such a width is not known) count as contact, not as gaps; without this the cusp
// between two tangent circles would be refined without end.
// Each such gap needs an element size h_gap = min(1, size_scale) * d / layers there; gaps so wide
// that h_gap >= air_size (the background size) are ignored. Samples along a segment are spaced at
// most h_gap / 2 wherever a gap is seen, and each detected gap becomes a size source: the
// segment from the sample to the hit point with size h_gap * (1 - grading / 4), so that with a
// grading slope `grading` every point of the gap (at most h_gap / 4 from a source segment) gets
// a size <= h_gap. Since a triangle's edges are bounded by that size, a straight line across the
// gap crosses at least `layers` elements.
#include <vector>

#include "mesh/size_field2d.hpp"

namespace magfem {

inline constexpr int owner_domain_boundary = -100; // owner of the outer (domain) circle

struct AirBoundary2D {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero();
  Vec2 normal = Vec2::Zero(); // unit, pointing into the air
  int owner = 0;              // part index or owner_domain_boundary
};

struct GapRuleOptions {
  int layers = 3;
  double size_scale = 1.0;
  double air_size = 0;  // target size of background air (already scaled), metres
  double grading = 0.5; // slope of the size field the sources will feed
  double min_width = 0; // narrower gaps are taken as contact (the outlines are not exact)
};

// Size sources (segments across every detected gap); empty when there is no thin gap.
std::vector<SizeSource2D> gap_sources(const std::vector<AirBoundary2D>& edges,
                                      const GapRuleOptions& options);

} // namespace magfem
