// The VTK module libmagfem_vtk.so (vtk_backend.hpp): the .vtu writer, the one user of VTK.
#include "postproc/vtk_backend.hpp"

#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace magfem {
namespace {

// VTK reads the grid's doubles in place (SetArray with save = 1: VTK neither copies nor frees
// them; the writer only reads, and the grid outlives it). Int32 arrays are converted.
vtkSmartPointer<vtkDataArray> make_array(const VtuArray& a) {
  const vtkIdType n = static_cast<vtkIdType>(a.values.size()) / a.components;
  if (a.type == VtuType::Int32) { // vtkIntArray is written as Int32 (VTK's int is 32 bits)
    vtkNew<vtkIntArray> arr;
    arr->SetName(a.name.c_str());
    arr->SetNumberOfComponents(a.components);
    arr->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n * a.components; ++i)
      arr->SetValue(i, static_cast<int>(a.values[i]));
    return vtkSmartPointer<vtkDataArray>(arr.GetPointer());
  }
  vtkNew<vtkDoubleArray> arr;
  arr->SetName(a.name.c_str());
  arr->SetNumberOfComponents(a.components);
  arr->SetArray(const_cast<double*>(a.values.data()), n * a.components, 1);
  return vtkSmartPointer<vtkDataArray>(arr.GetPointer());
}

vtkNew<vtkStringArray> make_strings(const VtuStrings& s) {
  vtkNew<vtkStringArray> arr;
  arr->SetName(s.name.c_str());
  arr->SetNumberOfValues(static_cast<vtkIdType>(s.values.size()));
  for (std::size_t i = 0; i < s.values.size(); ++i)
    arr->SetValue(static_cast<vtkIdType>(i), s.values[i]);
  return arr;
}

void write_vtu_with_vtk(const std::string& path, const VtuGrid& grid) {
  // The points in place too: Eigen::Vector3d is three packed doubles.
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetArray(const_cast<double*>(grid.points.empty() ? nullptr : grid.points[0].data()),
                static_cast<vtkIdType>(3 * grid.points.size()), 1);
  vtkNew<vtkPoints> points;
  points->SetData(xyz);

  // The cells as VTK's two arrays (offsets from 0, connectivity), filled in one pass each
  // rather than a cell at a time.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(grid.offsets.size()) + 1);
  offsets->SetValue(0, 0);
  for (std::size_t c = 0; c < grid.offsets.size(); ++c)
    offsets->SetValue(static_cast<vtkIdType>(c) + 1, grid.offsets[c]);
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(grid.connectivity.size()));
  for (std::size_t k = 0; k < grid.connectivity.size(); ++k)
    connectivity->SetValue(static_cast<vtkIdType>(k), grid.connectivity[k]);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  vtkNew<vtkUnstructuredGrid> ug;
  ug->SetPoints(points);
  ug->SetCells(const_cast<int*>(grid.cell_types.data()), cells);
  for (const auto& a : grid.point_data)
    ug->GetPointData()->AddArray(make_array(a));
  for (const auto& a : grid.cell_data)
    ug->GetCellData()->AddArray(make_array(a));
  for (const auto& s : grid.cell_names)
    ug->GetCellData()->AddArray(make_strings(s));
  for (const auto& s : grid.field_data)
    ug->GetFieldData()->AddArray(make_strings(s));

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(ug);
  // Appended raw binary, not inline base64 ("binary" mode): base64 encoding was most of the
  // writer's time (benchmark32, 1.5 M cells: 2.4 s CPU against 1.1 s raw) and a third more
  // bytes (374 against 280 MB). VTK's reader, and so ParaView, reads raw appended data alike;
  // the arrays read back are the same bits (VtuExport3D in tests/postproc/test_postproc3d.cpp).
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  // LZ4 rather than zlib: compressing with zlib was 15 % of a 100k-unknown axisymmetric run;
  // LZ4 compresses about ten times faster, and ParaView and VTK read it alike.
  writer->SetCompressorTypeToLZ4();
  if (writer->Write() != 1)
    throw std::runtime_error("cannot write " + path);
}

class Backend final : public VtkBackend {
public:
  void write_vtu(const std::string& path, const VtuGrid& grid) const override {
    write_vtu_with_vtk(path, grid);
  }
};

} // namespace
} // namespace magfem

// The one symbol the module exports (the rest is hidden: CMake's visibility preset).
extern "C" __attribute__((visibility("default"))) void* magfem_vtk_backend() {
  static const magfem::Backend backend;
  return const_cast<magfem::VtkBackend*>(static_cast<const magfem::VtkBackend*>(&backend));
}
