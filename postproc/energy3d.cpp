#include "postproc/energy3d.hpp"

#include <algorithm>
#include <array>

#include "core/constants.hpp"
#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "postproc/element_field3d.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

double energy_density(const Material& m, const Eigen::Vector3d& h) {
  double mu = 0, dmu = 0;
  m.permeability(h.squaredNorm(), mu, dmu);
  if (m.is_nonlinear())
    return m.curve->energy_density(mu * h.norm());
  return 0.5 * mu * h.squaredNorm(); // magnets: mu = mu0 mu_r, from the remanent state
}

std::size_t slot_of(int part, std::size_t n_parts) {
  if (part >= 0)
    return static_cast<std::size_t>(part);
  return part == region_background_3d ? n_parts : n_parts + 1;
}

struct ElementEnergy {
  double volume = 0, energy = 0, peak_B = 0;
};

// Volume, energy and (outside the shell, unless `known_peak`) peak |B| at the DOF nodes of
// tet t.
ElementEnergy element_energy(const Field3D& field, std::size_t t, bool known_peak) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  const bool in_shell = problem.is_shell(t);
  const Material& mat = *problem.physics(mesh.tet_part[t]).material;
  ElementEnergy e;
  const ElementField3D element(field, t); // the tet's geometry once for its 24 points
  // Curved (isoparametric) tets: the volume element varies over the tet.
  const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);
  for (int qi = 0; qi < static_cast<int>(rule.size()); ++qi) {
    const TetQuadPoint& q = rule[qi];
    ElementField3D::Point p;
    const Eigen::Vector3d h = element.H_at(qi, p);
    const double dv = q.weight * p.density;
    double w = 0;
    if (!in_shell) {
      w = energy_density(mat, h);
    } else if (problem.source && problem.source->active()) {
      // Physical H' = H_s(x') + J^-1 (-grad phi), energy density times |det J|.
      const Eigen::Vector3d hp = problem.source->table.H(t, qi) + shell.inverse_jacobian(p.x) * h;
      w = 0.5 * mu0 * hp.squaredNorm() * shell.det_jacobian(p.x);
    } else {
      w = 0.5 * mu0 * h.dot(shell.metric<3>(p.x) * h);
    }
    e.volume += dv;
    e.energy += dv * w;
  }
  if (in_shell || known_peak)
    return e;
  const int n_nodes = field.dofs().dofs_per_element();
  for (int i = 0; i < n_nodes; ++i)
    e.peak_B = std::max(e.peak_B, element.B_at_node(i).norm());
  return e;
}

} // namespace

EnergySummary3D summarize_energy_3d(const Field3D& field, const std::vector<std::string>& names,
                                    const std::vector<double>* element_peak_B) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  EnergySummary3D out;
  out.regions.resize(names.size() + 2);
  for (std::size_t i = 0; i < names.size(); ++i) {
    out.regions[i].name = names[i];
    out.regions[i].part = static_cast<int>(i);
    out.regions[i].nonlinear = problem.parts[i].material->is_nonlinear();
  }
  out.regions[names.size()] = {"air", region_background_3d, 0, 0, 0, false, {}};
  out.regions[names.size() + 1] = {"exterior (open boundary)", region_shell_3d, 0, 0, 0, false, {}};

  // Per element (volume, energy, peak |B|) on all cores, then summed in element order: the
  // same bits whatever the thread count.
  std::vector<ElementEnergy> share(mesh.n_tets());
  parallel_blocks(mesh.n_tets(), 4096, element_loop_threads(mesh.n_tets()),
                  [&](std::size_t, std::size_t lo, std::size_t hi) {
                    for (std::size_t t = lo; t < hi; ++t) {
                      share[t] = element_energy(field, t, element_peak_B != nullptr);
                      if (element_peak_B)
                        share[t].peak_B = (*element_peak_B)[t];
                    }
                  });
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    auto& reg = out.regions[slot_of(mesh.tet_part[t], names.size())];
    reg.volume_m3 += share[t].volume;
    reg.energy_J += share[t].energy;
    reg.peak_B_T = std::max(reg.peak_B_T, share[t].peak_B);
  }
  for (const auto& r : out.regions)
    out.total_J += r.energy_J;
  return out;
}

} // namespace magfem
