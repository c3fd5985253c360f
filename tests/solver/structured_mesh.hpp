#pragma once
// Structured triangle meshes of a rectangle for solver tests that must not depend on the
// CGAL mesher. The Dirichlet edges are chosen by the caller.
#include "mesh/mesh2d.hpp"

namespace magfem::test {

enum Side { left = 1, right = 2, bottom = 4, top = 8 };

inline Mesh2D structured_rectangle(double w, double h, int nx, int ny, int dirichlet_sides) {
  Mesh2D m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.nodes.emplace_back(w * i / nx, h * j / ny);
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // Alternate the diagonal so the mesh has no preferred direction.
      if ((i + j) % 2 == 0) {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
        m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  m.triangle_part.assign(m.triangles.size(), 0);
  for (int i = 0; i < nx; ++i) {
    if (dirichlet_sides & bottom) m.outer_edges.push_back({id(i, 0), id(i + 1, 0)});
    if (dirichlet_sides & top) m.outer_edges.push_back({id(i, ny), id(i + 1, ny)});
  }
  for (int j = 0; j < ny; ++j) {
    if (dirichlet_sides & left) m.outer_edges.push_back({id(0, j), id(0, j + 1)});
    if (dirichlet_sides & right) m.outer_edges.push_back({id(nx, j), id(nx, j + 1)});
  }
  return m;
}

} // namespace magfem::test
