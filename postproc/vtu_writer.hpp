#pragma once
// A mesh with point and cell arrays, written as a VTK XML unstructured grid (.vtu) for
// ParaView. This header is VTK-free; VTK is confined to the module (vtk_backend.hpp).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace magfem {

// How an array is stored in the file. Ids are Int32 so that ParaView offers them to
// Threshold and categorical colouring as the whole numbers they are.
enum class VtuType { Float64, Int32 };

struct VtuArray {
  std::string name;
  int components = 1;
  std::vector<double> values; // components * count, interleaved (Int32: whole numbers)
  VtuType type = VtuType::Float64;
};

// A string array: one name per cell (cell_names) or a table (field_data).
struct VtuStrings {
  std::string name;
  std::vector<std::string> values;
};

struct VtuGrid {
  std::vector<Eigen::Vector3d> points;
  std::vector<int>
      cell_types; // VTK cell type ids (5 triangle, 22 quadratic triangle, 10 tet, 24 quadratic tet)
  std::vector<int> offsets; // end offset of each cell in connectivity
  std::vector<int> connectivity;
  std::vector<VtuArray> point_data;
  std::vector<VtuArray> cell_data;
  std::vector<VtuStrings> cell_names; // string cell data (vtu_cell_names.hpp)
  std::vector<VtuStrings> field_data; // tables such as material_names
};

// Writes the grid without the points no cell uses (drop_unused_points, vtu_unused_points.hpp:
// the open boundary's shell is not written, its nodes would otherwise stay as stray points).
// Throws std::runtime_error if the file cannot be written. By value: the points are dropped
// from the caller's grid when it is moved in (a copy of benchmark32's grid was a quarter of the
// VTU's time).
void write_vtu(const std::string& path, VtuGrid grid);

} // namespace magfem
