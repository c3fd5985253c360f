#pragma once
// The solved 3D field: the scalar potential phi at every DOF, evaluated per element as the FE
// solution itself (H = -grad phi and B = mu H + B_r m_hat are discontinuous across elements).
// The smooth recovered B (per region, for probes and VTU point data) is RecoveredB3D
// (recovered_b3d.hpp). Shell tets (mapped exterior) are not physical space: B and H there are
// not evaluated by the recovery, the locator skips them.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map3d.hpp"
#include "solver/problem3d.hpp"

namespace magfem {

class Field3D {
public:
  // phi_full: the potential at every DOF (A), e.g. Assembler3D::expand(u).
  Field3D(const Problem3D& problem, const DofMap3D& dofs, Eigen::VectorXd phi_full);

  const Problem3D& problem() const { return problem_; }
  const DofMap3D& dofs() const { return dofs_; }
  const Eigen::VectorXd& phi() const { return phi_; }

  double potential(std::size_t t, const std::array<double, 4>& bary) const;
  // H = H_0 - grad phi in A/m: H_0 is the coils' source field in reduced regions and the
  // gradient of the source potential in total ones (coil_source3d.hpp); zero without coils.
  // Shell tets: -grad phi in the mesh's (mapped) coordinates, without the source.
  Eigen::Vector3d H(std::size_t t, const std::array<double, 4>& bary) const;
  // H and B at point q of tet_rule(SourceFieldTable3D::rule_degree), with the coils' field
  // from the source table: what integrals over the whole mesh (energy, flux linkage) use.
  Eigen::Vector3d H_at(std::size_t t, int q) const;
  Eigen::Vector3d B_at(std::size_t t, int q) const;
  // B at the element's DOF node i (tet_dof_nodes[i]), the coils' field from the source table.
  Eigen::Vector3d B_at_node(std::size_t t, int i) const;
  // B = mu(|H|^2) H + B_r m_hat(x) in T, from the region's law.
  Eigen::Vector3d B(std::size_t t, const std::array<double, 4>& bary) const;
  Eigen::Vector3d B_of_H(std::size_t t, const Eigen::Vector3d& x, const Eigen::Vector3d& h) const;
  // Remanent magnetization M0 = B_r m_hat / mu0 (A/m) at x in tet t; zero outside magnets.
  Eigen::Vector3d magnetization(std::size_t t, const Eigen::Vector3d& x) const;
  Eigen::Vector3d point(std::size_t t, const std::array<double, 4>& bary) const;
  // Volume element of tet t at bary relative to the barycentric measure (weights of
  // tet_rule sum to 1): the tet volume for straight tets, det J / 6 for curved ones.
  double volume_density(std::size_t t, const std::array<double, 4>& bary) const;

  // Gradients of the element's shape functions at bary (isoparametric for curved tets);
  // returns their number and the point in x.
  int shape_gradients(std::size_t t, const std::array<double, 4>& bary,
                      std::array<Eigen::Vector3d, 10>& grad, Eigen::Vector3d& x) const;

  // Interpolates nodal values (one per DOF) at a point of tet t with the element's shape
  // functions. The recovered B (one value per DOF and region) is RecoveredB3D's.
  Eigen::Vector3d interpolate(const std::vector<Eigen::Vector3d>& nodal, std::size_t t,
                              const std::array<double, 4>& bary) const;

  // Reduced tet outside the shell, with coils: H adds the coils' source field.
  bool adds_source(std::size_t t) const;

private:
  // grad of the potential (u, plus the source potential in total regions) at bary.
  Eigen::Vector3d grad_potential(std::size_t t, const std::array<double, 4>& bary) const;

  const Problem3D& problem_;
  const DofMap3D& dofs_;
  Eigen::VectorXd phi_;
};

} // namespace magfem
