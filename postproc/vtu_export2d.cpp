#include "postproc/vtu_export2d.hpp"

#include "postproc/vtu_cell_names.hpp"

namespace magfem {

VtuGrid make_vtu_2d(const Field2D& field, const std::vector<int>& material_of_part,
                    int air_material, const std::vector<std::string>& material_names,
                    const std::vector<std::string>& region_names) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  const auto& dofs = field.dofs();
  VtuGrid g;
  for (const auto& p : dofs.dof_points())
    g.points.emplace_back(p.x(), p.y(), 0.0);

  const auto b_nodes = field.recovered_B();
  const bool axi = problem.axisymmetric();
  // Axisymmetric flux lines are the contours of r A_phi (the flux through the circle of
  // radius r is 2 pi r A_phi), so that is written besides A_phi.
  VtuArray a{axi ? "A_phi" : "A_z", 1, {}}, psi{"r_A_phi", 1, {}}, bp{"B", 3, {}},
      bpm{"|B|", 1, {}};
  for (int i = 0; i < dofs.n_dofs(); ++i) {
    a.values.push_back(field.a()[i]);
    psi.values.push_back(dofs.dof_points()[i].x() * field.a()[i]);
    bp.values.insert(bp.values.end(), {b_nodes[i].x(), b_nodes[i].y(), 0.0});
    bpm.values.push_back(b_nodes[i].norm());
  }
  g.point_data = {a, bp, bpm};
  if (axi)
    g.point_data.push_back(psi);

  VtuArray region{"region_id", 1, {}, VtuType::Int32},
      material{"material_id", 1, {}, VtuType::Int32}, bc{"B", 3, {}}, bcm{"|B|", 1, {}},
      hc{"H", 3, {}};
  const int per = dofs.dofs_per_element();
  const int type = dofs.order() == 1 ? 5 : 22;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (problem.is_shell(t))
      continue;
    const int* dof = dofs.element_dofs(t);
    g.connectivity.insert(g.connectivity.end(), dof, dof + per);
    g.offsets.push_back(static_cast<int>(g.connectivity.size()));
    g.cell_types.push_back(type);
    const int part = mesh.triangle_part[t];
    region.values.push_back(part);
    material.values.push_back(part >= 0 ? material_of_part[part] : air_material);
    const std::array<double, 3> centroid = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    const Eigen::Vector2d b = field.B(t, centroid);
    const Eigen::Vector2d h = field.H(t, field.point(t, centroid), b);
    bc.values.insert(bc.values.end(), {b.x(), b.y(), 0.0});
    bcm.values.push_back(b.norm());
    hc.values.insert(hc.values.end(), {h.x(), h.y(), 0.0});
  }
  g.cell_data = {region, material, bc, bcm, hc};
  add_region_and_material_names(g, region_names, material_names);
  return g;
}

} // namespace magfem
