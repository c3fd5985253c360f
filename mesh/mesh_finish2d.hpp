#pragma once
// CGAL-free finishing steps of the 2D mesher on a Mesh2D: removal of the flat slivers that
// rounding leaves where a chord was split, boundary and interface edges, quality figures.
#include <array>
#include <vector>

#include "mesh/mesh2d.hpp"

namespace magfem {

// Neighbour of each triangle across each of its edges k (from vertex k to vertex k + 1), -1 on
// the boundary.
using Neighbours2D = std::vector<std::array<int, 3>>;

// Adjacency by sorting edge keys (for callers that have none at hand).
Neighbours2D neighbours(const Mesh2D& mesh);

// A triangle whose area is below sliver_area_ratio * (longest edge)^2 is a rounding artefact
// (a vertex inserted at a chord midpoint a hair off the chord); a triangle of a quality mesh
// has an area of at least ~0.2 (longest edge)^2.
inline constexpr double sliver_area_ratio = 1e-9;

// Removes slivers: the neighbour across a sliver's longest edge is split at the sliver's middle
// vertex (nothing is needed when that edge is on the boundary). Keeps the mesh conforming and
// `nb` up to date. Returns how many slivers were removed.
int remove_slivers(Mesh2D& mesh, Neighbours2D& nb);

// Edges with no neighbour, oriented with their triangle on the left (counter-clockwise around
// the domain).
std::vector<std::array<int, 2>> boundary_edges(const Mesh2D& mesh, const Neighbours2D& nb);

// Edges between a triangle of `region` and a triangle of another region, oriented with the
// `region` triangle on the left.
std::vector<std::array<int, 2>> interface_edges(const Mesh2D& mesh, const Neighbours2D& nb,
                                                int region);

// Min/max angle (degrees) and min signed area (m^2, <= 0 flags an inverted triangle).
MeshQuality2D measure_quality(const Mesh2D& mesh);

} // namespace magfem
