#pragma once
// A 10 mm box of structured tets (no TetGen) as a 3D problem: a magnet (B_r 1.2 T, mu_r 1.05,
// magnetized along (1, 2, 3)) in the lower half, iron (mu_r 50) in the upper half, air as the
// background material, and the given outer boundary kind.
#include <Eigen/Sparse>

#include "materials/magnetization.hpp"
#include "materials/material.hpp"
#include "solver/assembler3d.hpp"
#include "solver/problem3d.hpp"
#include "structured_mesh3d.hpp"

namespace magfem::test {

struct BoxProblem3D {
  Mesh3D mesh;
  Material air = Material::make_linear("air", 1.0, "test");
  Material iron = Material::make_linear("iron", 50.0, "test");
  Material magnet = Material::make_magnet("magnet", 1.2, 1.05, "test");
  Problem3D problem;

  BoxProblem3D(int n, int order, OuterKind3D boundary) {
    constexpr double mm = 1e-3;
    mesh = structured_box({0, 0, 0}, {10 * mm, 10 * mm, 10 * mm}, n);
    // Region 0 (magnet) in the lower half, region 1 (iron) in the upper half.
    for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k)
        c += 0.25 * mesh.nodes[mesh.tets[t][k]];
      mesh.tet_part[t] = c.z() < 5 * mm ? 0 : 1;
    }
    problem.mesh = &mesh;
    problem.order = order;
    problem.boundary = boundary;
    problem.air.material = &air;
    Magnetization m;
    m.pattern = Magnetization::Pattern::parallel;
    m.direction = Eigen::Vector3d(1, 2, 3).normalized();
    problem.parts = {{&magnet, m}, {&iron, {}}};
  }
};

// The P2 box with Dirichlet faces, assembled at u = 0: its tangent (lower triangle) and the
// magnet's load (minus the residual there), what the linear solver tests solve.
struct BoxTangent3D {
  BoxProblem3D box{6, 2, OuterKind3D::dirichlet};
  DofMap3D dofs{box.mesh, 2};
  Assembler3D a{box.problem, dofs};
  Eigen::SparseMatrix<double> lower;
  Eigen::VectorXd load;
  BoxTangent3D() {
    a.evaluate(Eigen::VectorXd::Zero(a.n_unknowns()), load, &lower, TangentKind::newton);
    load = -load;
  }
};

} // namespace magfem::test
