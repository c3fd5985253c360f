#pragma once
// Demagnetization check of the magnets of one solve: per magnet region the minimum of
// B . m_hat (the flux density along the local magnetization) against the knee of its grade
// (materials/magnet_knee.hpp). A point below the knee is past it: the magnet there loses
// part of its remanence irreversibly (the solve, a linear recoil model, does not know that).
//
// Where B . m_hat is read: at the vertices of every magnet element, from the element's own
// field (not a nodal average, which would mix in the neighbouring air or iron). Why vertices:
// at order 2, B is linear over a straight element (the gradient of a quadratic potential), so
// with a parallel magnetization B . m_hat is linear too and its minimum over the element lies
// at a vertex: the vertices give the exact minimum of the FE field, where quadrature points,
// inside the element, would miss the extreme on the magnet's surface, where demagnetization
// starts. (A radial magnetization or the axisymmetric A/r term makes it nearly linear: the
// vertices are then the natural sample.) At order 1, B is constant per element.
//
// One implementation for 2D planar, axisymmetric and 3D: the dimension's field gives the
// samples (demagnetization2d.hpp, demagnetization3d.hpp).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "materials/magnetization.hpp"
#include "materials/material.hpp"

namespace magfem {

struct DemagnetizationCheck {
  std::string region;
  std::string material;
  double temperature_C = 20;      // of the region (its grade's B_r and H_cJ at it)
  double min_B_along_M_T = 0;     // min over the magnet of B . m_hat
  Eigen::Vector3d at_m;           // where, in metres (2D: (x, y, 0), axisymmetric (r, z, 0))
  std::optional<double> knee_T;   // B_r(T) - mu0 mu_r H_cJ(T); none: the grade has no data
  std::optional<double> margin_T; // min - knee (negative: past the knee)
  bool at_risk = false;           // margin < 0

  // The console warning for a region at risk ("magnet 'x' ... below its knee ..."), the
  // place in the case's unit: (x, y) planar, (r, z) axisymmetric (dimension 2), (x, y, z).
  std::string warning(double length_unit, const std::string& unit_name, int dimension) const;
};

struct DemagnetizationResult {
  std::vector<DemagnetizationCheck> magnets; // magnet regions, in region order
  // Per element (mesh order, shell included): the minimum of B . m_hat over its vertices in
  // T; NaN outside magnets (0 would read as a flux density: a magnet exactly at B . m = 0 is
  // a real, critical value; NaN is "not a magnet", and ParaView leaves it uncoloured).
  std::vector<double> element_B_along_M;
};

// What the scan needs of one magnet region.
struct MagnetRegion {
  std::string name;
  const Material* material = nullptr; // nullptr: the region is not a magnet
  Magnetization magnetization;
};

// The regions of a problem's parts (RegionPhysics2D or 3D: material and magnetization), named
// by names[i]; non-magnets get no material.
template <class Physics>
std::vector<MagnetRegion> magnet_regions(const std::vector<Physics>& parts,
                                         const std::vector<std::string>& names) {
  std::vector<MagnetRegion> regions;
  for (std::size_t i = 0; i < parts.size(); ++i)
    regions.push_back({names.at(i), parts[i].material->is_magnet() ? parts[i].material : nullptr,
                       parts[i].magnetization});
  return regions;
}

// B and its position at vertex k of element t (metres, T; 2D with z = 0).
using VertexField =
    std::function<void(std::size_t t, int k, Eigen::Vector3d& x, Eigen::Vector3d& b)>;

// Scans every element whose part is a magnet (element_part[t] indexes regions; negative:
// air or shell) at its n_vertices vertices.
DemagnetizationResult scan_demagnetization(const std::vector<MagnetRegion>& regions,
                                           const std::vector<int>& element_part, int n_vertices,
                                           const VertexField& vertex_field);

} // namespace magfem
