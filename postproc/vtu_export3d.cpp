#include "postproc/vtu_export3d.hpp"

#include "postproc/vtu_cell_names.hpp"

#include "solver/coil_source3d.hpp"

namespace magfem {

VtuGrid make_vtu_3d(const Field3D& field, const std::vector<Eigen::Vector3d>& recovered_B,
                    const std::vector<int>& material_of_part, int air_material,
                    const std::vector<std::string>& material_names,
                    const std::vector<std::string>& region_names) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  const auto& dofs = field.dofs();
  VtuGrid g;
  g.points = dofs.dof_points();

  VtuArray phi{"phi", 1, {}}, bp{"B", 3, {}}, bpm{"|B|", 1, {}};
  phi.values.assign(field.phi().data(), field.phi().data() + field.phi().size());
  bp.values.reserve(3 * recovered_B.size());
  for (const auto& b : recovered_B) {
    bp.values.insert(bp.values.end(), {b.x(), b.y(), b.z()});
    bpm.values.push_back(b.norm());
  }
  g.point_data = {std::move(phi), std::move(bp), std::move(bpm)};
  const CoilSource3D* src = problem.source;
  const bool coils = src && src->active();
  if (coils) {
    // The coils' free-space field, and the reduced potential's meaning made visible.
    VtuArray hs{"H_s", 3, {}};
    for (int d = 0; d < static_cast<int>(g.points.size()); ++d) {
      const Eigen::Vector3d h = src->table.H_at_dof(d); // zero where only the shell has d
      hs.values.insert(hs.values.end(), {h.x(), h.y(), h.z()});
    }
    g.point_data.push_back(std::move(hs));
  }

  VtuArray region{"region_id", 1, {}, VtuType::Int32},
      material{"material_id", 1, {}, VtuType::Int32}, bc{"B", 3, {}}, bcm{"|B|", 1, {}},
      hc{"H", 3, {}}, mc{"magnetization", 3, {}}, jc{"J", 3, {}};
  const int per = dofs.dofs_per_element();
  const int type = dofs.order() == 1 ? 10 : 24;
  const std::array<double, 4> centroid = {0.25, 0.25, 0.25, 0.25};
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (problem.is_shell(t))
      continue;
    const int* dof = dofs.element_dofs(t);
    g.connectivity.insert(g.connectivity.end(), dof, dof + per);
    g.offsets.push_back(static_cast<int>(g.connectivity.size()));
    g.cell_types.push_back(type);
    const int part = mesh.tet_part[t];
    region.values.push_back(part);
    material.values.push_back(part >= 0 ? material_of_part[part] : air_material);
    const Eigen::Vector3d x = field.point(t, centroid);
    const Eigen::Vector3d h = field.H(t, centroid);
    const Eigen::Vector3d b = field.B_of_H(t, x, h);
    const Eigen::Vector3d m = field.magnetization(t, x);
    bc.values.insert(bc.values.end(), {b.x(), b.y(), b.z()});
    bcm.values.push_back(b.norm());
    hc.values.insert(hc.values.end(), {h.x(), h.y(), h.z()});
    mc.values.insert(mc.values.end(), {m.x(), m.y(), m.z()});
    if (coils) {
      // Coils are not meshed: J at the centroid shows where the bundles are.
      const Eigen::Vector3d j = src->field->J(x);
      jc.values.insert(jc.values.end(), {j.x(), j.y(), j.z()});
    }
  }
  g.cell_data = {region, material, bc, bcm, hc, mc};
  if (coils)
    g.cell_data.push_back(jc);
  add_region_and_material_names(g, region_names, material_names);
  return g;
}

} // namespace magfem
