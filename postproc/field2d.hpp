#pragma once
// The solved 2D field: A_z (planar) or A_phi (axisymmetric) at every DOF, evaluated per element as
// the FE solution itself (B = curl A is discontinuous across elements) or recovered at nodes by
// area-weighted averaging (smooth, for plots and VTU point data).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "solver/dof_map2d.hpp"
#include "solver/problem2d.hpp"

namespace magfem {

class Field2D {
public:
  Field2D(const Problem2D& problem, const DofMap2D& dofs, Eigen::VectorXd a_full);

  const Problem2D& problem() const { return problem_; }
  const DofMap2D& dofs() const { return dofs_; }
  const Eigen::VectorXd& a() const { return a_; }

  double A(std::size_t t, const std::array<double, 3>& bary) const;
  Eigen::Vector2d B(std::size_t t, const std::array<double, 3>& bary) const;
  // H from the region's law, including the remanence of magnets (at point x).
  Eigen::Vector2d H(std::size_t t, const Eigen::Vector2d& x, const Eigen::Vector2d& b) const;
  Eigen::Vector2d point(std::size_t t, const std::array<double, 3>& bary) const;

  // Area-weighted average of the element B values at every DOF point (shell excluded), over
  // all regions at the DOF: it mixes materials at their boundaries (B_t jumps by mu_r), so it
  // is for VTU point data only; probes read the element field (probes2d.hpp).
  std::vector<Eigen::Vector2d> recovered_B() const;

private:
  const Problem2D& problem_;
  const DofMap2D& dofs_;
  Eigen::VectorXd a_;
};

} // namespace magfem
