#pragma once
// Lagrange shape functions on a straight-sided tetrahedron, orders 1 and 2, in barycentric
// coordinates L. Local numbering (the VTK quadratic-tet order, so VTU export is direct):
// vertices 0..3, then (order 2) the midpoints of the edges (0,1), (1,2), (2,0), (0,3), (1,3),
// (2,3).
#include <array>

#include <Eigen/Core>
#include <Eigen/LU>

namespace magfem {

struct TetGeometry {
  std::array<Eigen::Vector3d, 4> grad_L; // gradients of the barycentric coordinates (1/m)
  double volume = 0;                     // m^3, > 0 for positively oriented tets

  static TetGeometry of(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                        const Eigen::Vector3d& p2, const Eigen::Vector3d& p3) {
    TetGeometry g;
    Eigen::Matrix3d j;
    j.col(0) = p1 - p0;
    j.col(1) = p2 - p0;
    j.col(2) = p3 - p0;
    const double det = j.determinant();
    g.volume = det / 6.0;
    // Rows of J^-1 are the gradients of L1, L2, L3; L0 = 1 - L1 - L2 - L3.
    const Eigen::Matrix3d inv = j.inverse();
    for (int k = 0; k < 3; ++k)
      g.grad_L[k + 1] = inv.row(k).transpose();
    g.grad_L[0] = -(g.grad_L[1] + g.grad_L[2] + g.grad_L[3]);
    return g;
  }
};

inline constexpr int tet_dofs(int order) {
  return order == 1 ? 4 : 10;
}
inline constexpr std::array<std::array<int, 2>, 6> tet_edges = {
    {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};

// Barycentric coordinates of the local DOF nodes (vertices, then edge midpoints).
inline constexpr std::array<std::array<double, 4>, 10> tet_dof_nodes = {{{1, 0, 0, 0},
                                                                         {0, 1, 0, 0},
                                                                         {0, 0, 1, 0},
                                                                         {0, 0, 0, 1},
                                                                         {0.5, 0.5, 0, 0},
                                                                         {0, 0.5, 0.5, 0},
                                                                         {0.5, 0, 0.5, 0},
                                                                         {0.5, 0, 0, 0.5},
                                                                         {0, 0.5, 0, 0.5},
                                                                         {0, 0, 0.5, 0.5}}};

// Values of the shape functions at barycentric point L; returns the count.
inline int tet_values(int order, const std::array<double, 4>& L, double* n) {
  if (order == 1) {
    for (int i = 0; i < 4; ++i)
      n[i] = L[i];
    return 4;
  }
  for (int i = 0; i < 4; ++i)
    n[i] = L[i] * (2 * L[i] - 1);
  for (int e = 0; e < 6; ++e)
    n[4 + e] = 4 * L[tet_edges[e][0]] * L[tet_edges[e][1]];
  return 10;
}

// Gradients of the shape functions at barycentric point L (1/m); returns the count.
inline int tet_gradients(int order, const TetGeometry& g, const std::array<double, 4>& L,
                         Eigen::Vector3d* grad) {
  if (order == 1) {
    for (int i = 0; i < 4; ++i)
      grad[i] = g.grad_L[i];
    return 4;
  }
  for (int i = 0; i < 4; ++i)
    grad[i] = (4 * L[i] - 1) * g.grad_L[i];
  for (int e = 0; e < 6; ++e) {
    const int a = tet_edges[e][0], b = tet_edges[e][1];
    grad[4 + e] = 4 * (L[b] * g.grad_L[a] + L[a] * g.grad_L[b]);
  }
  return 10;
}

// Isoparametric order-2 map of a curved tet from its 10 node positions x (vertices, then edge
// nodes, which may lie off the edge midpoints), at barycentric point L: the physical point,
// the Jacobian dx / dxi (with the reference gradients of the 10 shape functions in g_ref),
// and from them tet_iso_gradients. The point and the volume element alone skip the inverse:
// post-processing asks for them at far more points than for the gradients.
inline Eigen::Vector3d tet_iso_point(const std::array<Eigen::Vector3d, 10>& x,
                                     const std::array<double, 4>& L) {
  std::array<double, 10> n{};
  tet_values(2, L, n.data());
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (int i = 0; i < 10; ++i)
    point += n[i] * x[i];
  return point;
}

inline Eigen::Matrix3d tet_iso_jacobian(const std::array<Eigen::Vector3d, 10>& x,
                                        const std::array<double, 4>& L,
                                        std::array<Eigen::Vector3d, 10>& g_ref) {
  static const TetGeometry reference = TetGeometry::of({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  tet_gradients(2, reference, L, g_ref.data());
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 10; ++i)
    j += x[i] * g_ref[i].transpose();
  return j;
}

// det J / 6: the volume element relative to the barycentric measure (the straight tet's
// volume when the edge nodes are midpoints).
inline double tet_iso_density(const std::array<Eigen::Vector3d, 10>& x,
                              const std::array<double, 4>& L) {
  std::array<Eigen::Vector3d, 10> g_ref;
  return tet_iso_jacobian(x, L, g_ref).determinant() / 6.0;
}

// The physical gradients of the 10 shape functions, the physical point, and the return value
// det J / 6 (tet_iso_density).
inline double tet_iso_gradients(const std::array<Eigen::Vector3d, 10>& x,
                                const std::array<double, 4>& L, Eigen::Vector3d* grad,
                                Eigen::Vector3d& point) {
  std::array<Eigen::Vector3d, 10> g_ref;
  const Eigen::Matrix3d j = tet_iso_jacobian(x, L, g_ref);
  point = tet_iso_point(x, L);
  const Eigen::Matrix3d inv_t = j.inverse().transpose();
  for (int i = 0; i < 10; ++i)
    grad[i] = inv_t * g_ref[i];
  return j.determinant() / 6.0;
}

} // namespace magfem
