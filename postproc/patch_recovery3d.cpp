#include "postproc/patch_recovery3d.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <utility>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "mesh/vertex_tets3d.hpp"
#include "postproc/element_field3d.hpp"
#include "postproc/patch_fit.hpp"
#include "solver/coil_source3d.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {

using Fit = PatchFit<3>;
using Sample = Fit::Sample;

} // namespace

Eigen::Vector3d PatchRecovery3D::G_h(std::size_t t, const std::array<double, 4>& bary) const {
  return -ElementField3D(field_, t).at(bary).grad_phi;
}

PatchRecovery3D::PatchRecovery3D(const Field3D& field, int threads) : field_(field) {
  const Problem3D& problem = field.problem();
  const Mesh3D& mesh = *problem.mesh;
  const DofMap3D& dofs = field.dofs();
  const int n_vertices = dofs.n_vertices();
  slots_ = RegionSlots(
      dofs.n_dofs(), mesh.n_tets(), dofs.dofs_per_element(),
      [&](std::size_t t) { return dofs.element_dofs(t); },
      [&](std::size_t t) { return mesh.tet_part[t]; });
  if (threads <= 0)
    threads = element_loop_threads(mesh.n_tets());

  const VertexTets3D around(mesh);

  // The 4-point rule of degree 2 for both orders: exact for order 1's normal equations;
  // for order 2 (quartic matrix entries) the 14-point degree-5 rule is exact, but on the
  // magnetized-sphere tests it moved the effectivity by under 0.5 % (1.024 -> 1.020, 1.000
  // -> 0.995) at 3.5x the cost, and the fits are most of the estimator's time.
  const auto& rule = tet_rule(2);
  // What the ~20 patches a tet belongs to read from it, computed once per tet: G_h at the
  // corners of a straight tet (linear in the barycentric coordinates there, constant for
  // order 1; kept: the indicator reads them again) and its volume; the samples themselves
  // of a curved tet (on spheres, 15 % of benchmark32's tets, whose isoparametric gradients
  // were half the estimator's time when every patch recomputed them).
  std::vector<std::array<Eigen::Vector3d, 4>>& corner = corner_;
  corner.resize(mesh.n_tets());
  std::vector<double> volume(mesh.n_tets(), 0.0);
  std::vector<int> curved_index(mesh.n_tets(), -1);
  int n_curved = 0;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (dofs.is_curved(t))
      curved_index[t] = n_curved++;
  std::vector<std::array<Sample, 4>> curved_samples(static_cast<std::size_t>(n_curved));
  parallel_blocks(mesh.n_tets(), 4096, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t t = lo; t < hi; ++t) {
      const ElementField3D element(field, t);
      if (curved_index[t] < 0) {
        for (int i = 0; i < 4; ++i)
          corner[t][i] = -element.at(tet_dof_nodes[i]).grad_phi;
        volume[t] = element.at(tet_dof_nodes[0]).density;
        continue;
      }
      for (std::size_t i = 0; i < rule.size(); ++i) {
        const ElementField3D::Point p = element.at(rule[i].bary);
        curved_samples[curved_index[t]][i] = {p.x, -p.grad_phi, rule[i].weight * p.density};
      }
    }
  });
  auto add_samples = [&](std::size_t t, std::vector<Sample>& out) {
    if (curved_index[t] >= 0) {
      const auto& own = curved_samples[curved_index[t]];
      out.insert(out.end(), own.begin(), own.end());
      return;
    }
    const auto& k = mesh.tets[t];
    for (const auto& q : rule) {
      const auto& l = q.bary;
      Sample s;
      s.w = q.weight * volume[t];
      s.x = l[0] * mesh.nodes[k[0]] + l[1] * mesh.nodes[k[1]] + l[2] * mesh.nodes[k[2]] +
            l[3] * mesh.nodes[k[3]];
      s.g = l[0] * corner[t][0] + l[1] * corner[t][1] + l[2] * corner[t][2] + l[3] * corner[t][3];
      out.push_back(s);
    }
  };

  // One fit per (vertex, region): vertex slots come first (DOFs 0 .. n_vertices - 1).
  const int degree = dofs.order();
  std::vector<Fit> fits(slots_.begin(n_vertices));
  std::atomic<std::size_t> degraded{0};
  parallel_blocks(n_vertices, 512, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    std::vector<int> patch;
    std::vector<Sample> pts;
    for (std::size_t v = lo; v < hi; ++v) {
      for (int s = slots_.begin(v); s < slots_.end(v); ++s) {
        const int part = slots_.part(s);
        patch.clear();
        for (int n : around.of(v))
          if (mesh.tet_part[n] == part)
            patch.push_back(n);
        if (static_cast<int>(patch.size()) < min_patch_tets) {
          const std::vector<int> ring(patch);
          for (int t : ring)
            for (int w : mesh.tets[t])
              for (int n : around.of(w))
                if (mesh.tet_part[n] == part)
                  patch.push_back(n);
          std::sort(patch.begin(), patch.end());
          patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
        }
        pts.clear();
        for (int t : patch)
          add_samples(static_cast<std::size_t>(t), pts);
        fits[s] = Fit::fit(pts, mesh.nodes[v], degree);
        if (fits[s].degree < degree)
          ++degraded;
      }
    }
  });
  n_degraded_ = degraded;

  // Nodal values: a vertex its own fit, an edge node the mean of its two ends' fits there.
  value_.assign(slots_.size(), Eigen::Vector3d::Zero());
  for (int v = 0; v < n_vertices; ++v)
    for (int s = slots_.begin(v); s < slots_.end(v); ++s)
      value_[s] = fits[s].at(mesh.nodes[v]);
  for (int d = n_vertices; d < dofs.n_dofs(); ++d) {
    const auto ends = dofs.edge_ends(d);
    const Eigen::Vector3d& x = dofs.dof_points()[d];
    for (int s = slots_.begin(d); s < slots_.end(d); ++s)
      value_[s] = 0.5 * (fits[slots_.own_slot(ends[0], slots_.part(s))].at(x) +
                         fits[slots_.own_slot(ends[1], slots_.part(s))].at(x));
  }
  keep_radial_at_infinity();
}

void PatchRecovery3D::keep_radial_at_infinity() {
  const Problem3D& problem = field_.problem();
  const Mesh3D& mesh = *problem.mesh;
  if (problem.boundary != OuterKind3D::open)
    return;
  for (int d : field_.dofs().dofs_on_faces(mesh.outer_faces)) {
    const int s = slots_.slot(d, region_shell_3d);
    if (s < 0)
      continue;
    const Eigen::Vector3d e = field_.dofs().dof_points()[d].normalized();
    value_[s] = e * e.dot(value_[s]);
  }
}

int PatchRecovery3D::nodal_values(std::size_t t, std::array<Eigen::Vector3d, 10>& out) const {
  const DofMap3D& dofs = field_.dofs();
  const int* dof = dofs.element_dofs(t);
  const int part = field_.problem().mesh->tet_part[t];
  const int n = dofs.dofs_per_element();
  for (int i = 0; i < n; ++i)
    out[i] = value_[slots_.own_slot(dof[i], part)];
  return n;
}

Eigen::Vector3d PatchRecovery3D::G(std::size_t t, const std::array<double, 4>& bary) const {
  const DofMap3D& dofs = field_.dofs();
  std::array<double, 10> n{};
  const int count = tet_values(dofs.order(), bary, n.data());
  const int* dof = dofs.element_dofs(t);
  const int part = field_.problem().mesh->tet_part[t];
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (int i = 0; i < count; ++i)
    g += n[i] * value_[slots_.own_slot(dof[i], part)];
  return g;
}

Eigen::Vector3d PatchRecovery3D::H_at(std::size_t t, const std::array<double, 4>& bary,
                                      const Eigen::Vector3d& x) const {
  Eigen::Vector3d h = G(t, bary);
  const CoilSource3D* src = field_.problem().source;
  if (src && src->active() && !src->is_total(t))
    h += src->field->H(x);
  return h;
}

Eigen::Vector3d PatchRecovery3D::H(std::size_t t, const std::array<double, 4>& bary) const {
  return H_at(t, bary, field_.point(t, bary));
}

Eigen::Vector3d PatchRecovery3D::B(std::size_t t, const std::array<double, 4>& bary) const {
  const Eigen::Vector3d x = field_.point(t, bary);
  return field_.B_of_H(t, x, H_at(t, bary, x));
}

} // namespace magfem
