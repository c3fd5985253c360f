#pragma once
// Lagrange shape functions on a straight-sided triangle, orders 1 and 2, in barycentric
// coordinates L. Local numbering: vertices 0,1,2, then (order 2) the midpoints of the edges
// (0,1), (1,2), (2,0).
#include <array>

#include <Eigen/Core>

namespace magfem {

struct TriangleGeometry {
  std::array<Eigen::Vector2d, 3> grad_L; // gradients of the barycentric coordinates
  double area = 0;

  static TriangleGeometry of(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                             const Eigen::Vector2d& p2) {
    TriangleGeometry g;
    const double det = (p1 - p0).x() * (p2 - p0).y() - (p2 - p0).x() * (p1 - p0).y();
    g.area = 0.5 * det;
    // grad L_i is the inward normal of the opposite edge divided by twice the area.
    g.grad_L[0] = Eigen::Vector2d(p1.y() - p2.y(), p2.x() - p1.x()) / det;
    g.grad_L[1] = Eigen::Vector2d(p2.y() - p0.y(), p0.x() - p2.x()) / det;
    g.grad_L[2] = Eigen::Vector2d(p0.y() - p1.y(), p1.x() - p0.x()) / det;
    return g;
  }
};

inline constexpr int triangle_dofs(int order) { return order == 1 ? 3 : 6; }
inline constexpr std::array<std::array<int, 2>, 3> triangle_edges = {{{0, 1}, {1, 2}, {2, 0}}};

// Values of the shape functions at barycentric point L; returns the count.
inline int triangle_values(int order, const std::array<double, 3>& L, double* n) {
  if (order == 1) {
    for (int i = 0; i < 3; ++i) n[i] = L[i];
    return 3;
  }
  for (int i = 0; i < 3; ++i) n[i] = L[i] * (2 * L[i] - 1);
  for (int e = 0; e < 3; ++e) n[3 + e] = 4 * L[triangle_edges[e][0]] * L[triangle_edges[e][1]];
  return 6;
}

// Gradients of the shape functions at barycentric point L; returns the count.
inline int triangle_gradients(int order, const TriangleGeometry& g, const std::array<double, 3>& L,
                              Eigen::Vector2d* grad) {
  if (order == 1) {
    for (int i = 0; i < 3; ++i) grad[i] = g.grad_L[i];
    return 3;
  }
  for (int i = 0; i < 3; ++i) grad[i] = (4 * L[i] - 1) * g.grad_L[i];
  for (int e = 0; e < 3; ++e) {
    const int a = triangle_edges[e][0], b = triangle_edges[e][1];
    grad[3 + e] = 4 * (L[b] * g.grad_L[a] + L[a] * g.grad_L[b]);
  }
  return 6;
}

} // namespace magfem
