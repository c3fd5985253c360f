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

template <class Array, class Value> vtkSmartPointer<vtkDataArray> filled(const VtuArray& a) {
  vtkNew<Array> arr;
  arr->SetName(a.name.c_str());
  arr->SetNumberOfComponents(a.components);
  const vtkIdType n = static_cast<vtkIdType>(a.values.size()) / a.components;
  arr->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n * a.components; ++i)
    arr->SetValue(i, static_cast<Value>(a.values[i]));
  return vtkSmartPointer<vtkDataArray>(arr.GetPointer());
}

vtkSmartPointer<vtkDataArray> make_array(const VtuArray& a) {
  // vtkIntArray is written as Int32 (VTK's int is 32 bits on every platform it supports).
  return a.type == VtuType::Int32 ? filled<vtkIntArray, int>(a) : filled<vtkDoubleArray, double>(a);
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
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(grid.points.size()));
  for (std::size_t i = 0; i < grid.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), grid.points[i].data());

  vtkNew<vtkCellArray> cells;
  int begin = 0;
  std::vector<vtkIdType> ids;
  for (const int end : grid.offsets) {
    ids.assign(grid.connectivity.begin() + begin, grid.connectivity.begin() + end);
    cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    begin = end;
  }
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
