#pragma once
// What the 3D scalar-potential solver needs to know about each region: its material law and
// the remanence pattern of magnets. Built by the case reader from the case file and the
// mesh; the solver never sees YAML. Coils enter through `source` (coil_source3d.hpp).
#include <vector>

#include "materials/magnetization.hpp"
#include "materials/material.hpp"
#include "mesh/geometry3d.hpp"
#include "mesh/mesh3d.hpp"

namespace magfem {
struct CoilSource3D;
}

namespace magfem {

struct RegionPhysics3D {
  const Material* material = nullptr; // never null once built
  Magnetization magnetization;        // magnets only; B_r comes from the material
};

struct Problem3D {
  const Mesh3D* mesh = nullptr;
  int order = 2;
  std::vector<RegionPhysics3D> parts; // indexed like Geometry3D::parts
  RegionPhysics3D air;                // background air and the open-boundary shell
  OuterKind3D boundary = OuterKind3D::open;
  const CoilSource3D* source = nullptr; // coils (two-potential split); null = none

  const RegionPhysics3D& physics(int part) const {
    return part >= 0 ? parts[static_cast<std::size_t>(part)] : air;
  }
  bool is_shell(std::size_t tet) const { return mesh->tet_part[tet] == region_shell_3d; }
};

} // namespace magfem
