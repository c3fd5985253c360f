#include "postproc/recovered_b3d.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/parallel_scatter.hpp"
#include "core/thread_count.hpp"
#include "postproc/element_field3d.hpp"
#include "solver/tet_lagrange.hpp"

namespace magfem {

RecoveredB3D::RecoveredB3D(const Field3D& field, int threads)
    : mesh_(field.problem().mesh), dofs_(&field.dofs()) {
  const Problem3D& problem = field.problem();
  const Mesh3D& mesh = *mesh_;
  const int n = dofs_->dofs_per_element();
  slots_ = RegionSlots(
      dofs_->n_dofs(), mesh.n_tets(), n, [&](std::size_t t) { return dofs_->element_dofs(t); },
      [&](std::size_t t) { return problem.is_shell(t) ? RegionSlots::skip : mesh.tet_part[t]; });
  b_.assign(slots_.size(), Eigen::Vector3d::Zero());
  weight_.assign(slots_.size(), 0.0);
  element_peak_B_.assign(mesh.n_tets(), 0.0);
  if (threads <= 0)
    threads = element_loop_threads(mesh.n_tets());
  // Per element and local DOF: vol B (3 values), vol and the slot (exact as a double). Each
  // slot is summed by one thread in element order: the result does not depend on the count.
  parallel_element_scatter(
      mesh.n_tets(), 5 * n, b_.size(), threads,
      [&](std::size_t t, double* out) {
        if (problem.is_shell(t))
          return;
        const auto& tet = mesh.tets[t];
        const double vol = TetGeometry::of(mesh.nodes[tet[0]], mesh.nodes[tet[1]],
                                           mesh.nodes[tet[2]], mesh.nodes[tet[3]])
                               .volume;
        const int* dof = dofs_->element_dofs(t);
        const ElementField3D element(field, t);
        double peak = 0;
        for (int i = 0; i < n; ++i) {
          const Eigen::Vector3d b_node = element.B_at_node(i);
          peak = std::max(peak, b_node.norm());
          const Eigen::Vector3d b = vol * b_node;
          double* o = out + 5 * i;
          o[0] = b.x(), o[1] = b.y(), o[2] = b.z(), o[3] = vol;
          o[4] = slots_.own_slot(dof[i], mesh.tet_part[t]);
        }
        element_peak_B_[t] = peak;
      },
      [&](std::size_t t, const double* v, std::size_t lo, std::size_t hi) {
        if (problem.is_shell(t))
          return;
        for (int i = 0; i < n; ++i) {
          const double* o = v + 5 * i;
          const auto s = static_cast<std::size_t>(o[4]);
          if (s >= lo && s < hi) {
            b_[s] += Eigen::Vector3d(o[0], o[1], o[2]);
            weight_[s] += o[3];
          }
        }
      });
  for (std::size_t s = 0; s < b_.size(); ++s)
    b_[s] /= weight_[s]; // every slot has a tet of positive volume
}

const Eigen::Vector3d& RecoveredB3D::value(int dof, int part) const {
  const int s = slots_.slot(dof, part);
  if (s < 0)
    throw std::out_of_range("recovered B: region " + std::to_string(part) + " does not touch DOF " +
                            std::to_string(dof));
  return b_[s];
}

Eigen::Vector3d RecoveredB3D::at(std::size_t t, const std::array<double, 4>& bary) const {
  std::array<double, 10> n{};
  const int count = tet_values(dofs_->order(), bary, n.data());
  const int* dof = dofs_->element_dofs(t);
  const int part = mesh_->tet_part[t];
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i)
    v += n[i] * b_[slots_.own_slot(dof[i], part)];
  return v;
}

std::vector<Eigen::Vector3d> RecoveredB3D::dof_average() const {
  std::vector<Eigen::Vector3d> out(slots_.n_dofs(), Eigen::Vector3d::Zero());
  for (int d = 0; d < slots_.n_dofs(); ++d) {
    const int lo = slots_.begin(d), hi = slots_.end(d);
    if (hi - lo == 1) {
      out[d] = b_[lo];
      continue;
    }
    double w = 0;
    for (int s = lo; s < hi; ++s) {
      out[d] += weight_[s] * b_[s];
      w += weight_[s];
    }
    if (w > 0)
      out[d] /= w;
  }
  return out;
}

} // namespace magfem
