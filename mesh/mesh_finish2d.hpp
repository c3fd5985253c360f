#pragma once
// CGAL-free finishing steps of the 2D mesher on a Mesh2D: removal of the flat slivers that
// rounding leaves where a chord was split, boundary edges, and quality figures.
#include <array>
#include <vector>

#include "mesh/mesh2d.hpp"

namespace magfem {

// A triangle whose area is below sliver_area_ratio * (longest edge)^2 is a rounding artefact
// (a vertex inserted at a chord midpoint a hair off the chord); a real triangle of a quality
// mesh has an area of at least ~0.2 (longest edge)^2.
inline constexpr double sliver_area_ratio = 1e-9;

// Removes slivers: the sliver's middle vertex is moved into the edge it lies on, i.e. the
// neighbour across the sliver's longest edge is split at that vertex (or nothing is needed when
// the longest edge is on the boundary). Keeps the mesh conforming. Returns how many were removed.
int remove_slivers(Mesh2D& mesh);

// Edges with a single triangle, oriented with that triangle on the left (counter-clockwise
// around the domain).
std::vector<std::array<int, 2>> boundary_edges(const Mesh2D& mesh);

// Edges between a triangle of `region` and a triangle of another region, oriented with the
// `region` triangle on the left.
std::vector<std::array<int, 2>> interface_edges(const Mesh2D& mesh, int region);

// Min/max angle (degrees) and min signed area (m^2, <= 0 flags an inverted triangle).
MeshQuality2D measure_quality(const Mesh2D& mesh);

} // namespace magfem
