#pragma once
// What the 2D A_z solver needs to know about each region: its material law, the remanence
// pattern of magnets and the impressed current density. Built by the case reader from the
// case file and the mesh; the solver never sees YAML.
#include <vector>

#include "materials/magnetization.hpp"
#include "materials/material.hpp"
#include "mesh/geometry2d.hpp"
#include "mesh/mesh2d.hpp"

namespace magfem {

struct RegionPhysics2D {
  const Material* material = nullptr; // never null once built
  Magnetization magnetization;        // magnets only; B_r comes from the material
  double current_density = 0;         // J_z (planar) or J_phi (axisymmetric) in A/m^2
};

struct Problem2D {
  const Mesh2D* mesh = nullptr;
  Symmetry2D symmetry = Symmetry2D::planar; // axisymmetric: A is A_phi, J is J_phi
  int order = 2;
  std::vector<RegionPhysics2D> parts; // indexed like Geometry2D::parts
  RegionPhysics2D air;                // background air and the open-boundary shell
  OuterKind boundary = OuterKind::open;

  const RegionPhysics2D& physics(int part) const {
    return part >= 0 ? parts[static_cast<std::size_t>(part)] : air;
  }
  bool is_shell(std::size_t triangle) const { return mesh->triangle_part[triangle] == region_shell; }
  bool axisymmetric() const { return symmetry == Symmetry2D::axisymmetric; }
};

} // namespace magfem
