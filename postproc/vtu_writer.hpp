#pragma once
// A mesh with point and cell arrays, written as a VTK XML unstructured grid (.vtu) for
// ParaView. This header is VTK-free; VTK is confined to the module (vtk_backend.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace magfem {

struct VtuArray {
  std::string name;
  int components = 1;
  std::vector<double> values; // components * count, interleaved
};

struct VtuGrid {
  std::vector<Eigen::Vector3d> points;
  std::vector<int>
      cell_types; // VTK cell type ids (5 triangle, 22 quadratic triangle, 10 tet, 24 quadratic tet)
  std::vector<int> offsets; // end offset of each cell in connectivity
  std::vector<int> connectivity;
  std::vector<VtuArray> point_data;
  std::vector<VtuArray> cell_data;
  std::vector<std::string> material_names; // stored as field data "material_names"
};

// Throws std::runtime_error if the file cannot be written.
void write_vtu(const std::string& path, const VtuGrid& grid);

} // namespace magfem
