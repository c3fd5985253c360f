#pragma once
// A 3D field on a structured box (no TetGen, milliseconds) with a prescribed potential, for
// tests of postprocessing that need a field whose values are known everywhere: a 10 mm box of
// 6^3 cubes (node planes every 5/3 mm, one at 0), filled with air, or with a magnet (mu_r 1.1,
// B_r 1 T along x) below z = 0 and iron (mu_r 10) at z > 0, x < 0; phi_at(x) gives the
// potential (A) at every DOF point (metres).
#include <memory>

#include "../solver/structured_mesh3d.hpp"
#include "materials/material.hpp"
#include "postproc/field3d.hpp"
#include "solver/dof_map3d.hpp"
#include "solver/problem3d.hpp"

namespace magfem::test {

// A harmonic quadratic potential (A) and its field H = -grad phi (A/m), x in metres: P2 holds
// it exactly and H is linear, so B is linear in every straight tet.
inline double phi_exact(const Eigen::Vector3d& x) {
  return 1e6 * (x.x() * x.x() - x.y() * x.y() + 3 * x.y() * x.z()) + 2e3 * x.z();
}
inline Eigen::Vector3d h_exact(const Eigen::Vector3d& x) {
  return -Eigen::Vector3d(2e6 * x.x(), 1e6 * (-2 * x.y() + 3 * x.z()), 3e6 * x.y() + 2e3);
}

struct BoxField3D {
  Material air = Material::make_linear("air", 1.0, "test");
  Material iron = Material::make_linear("iron", 10.0, "test");
  Material magnet = Material::make_magnet("magnet", 1.0, 1.1, "test");
  Mesh3D mesh = structured_box({-5e-3, -5e-3, -5e-3}, {5e-3, 5e-3, 5e-3}, 6);
  Problem3D problem;
  std::unique_ptr<DofMap3D> dofs;
  std::unique_ptr<Field3D> field;

  template <class Phi> BoxField3D(int order, bool regions, const Phi& phi_at) {
    if (regions)
      for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k)
          c += 0.25 * mesh.nodes[mesh.tets[t][k]];
        mesh.tet_part[t] = c.z() < 0 ? 0 : (c.x() < 0 ? 1 : region_background_3d);
      }
    problem.mesh = &mesh;
    problem.order = order;
    problem.boundary = OuterKind3D::dirichlet;
    problem.air.material = &air;
    Magnetization m;
    m.pattern = Magnetization::Pattern::parallel;
    m.direction = Eigen::Vector3d::UnitX();
    problem.parts = {{&magnet, m}, {&iron, {}}};
    if (!regions)
      problem.parts = {{&air, {}}};
    dofs = std::make_unique<DofMap3D>(mesh, order);
    Eigen::VectorXd phi(dofs->n_dofs());
    for (int d = 0; d < dofs->n_dofs(); ++d)
      phi[d] = phi_at(dofs->dof_points()[d]);
    field = std::make_unique<Field3D>(problem, *dofs, phi);
  }
  // Field3D and the problem hold pointers into this object.
  BoxField3D(const BoxField3D&) = delete;
  BoxField3D& operator=(const BoxField3D&) = delete;
};

} // namespace magfem::test
