// solution.vtu as ParaView reads it (issue 34 item 9), read back through VTK's XML reader:
//   region_id and material_id are Int32 (ids, not measurements), the cell string arrays
//   `region` and `material` name every cell (ParaView colours by them with a legend of names),
//   field data region_names and material_names map the ids to names;
//   every point is used by a cell: the open boundary's shell is not written and its nodes are
//   dropped, the point data renumbered with them, so B at a file point is the recovered B of
//   the DOF at the same coordinates (exact equality: both are the same doubles, copied).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <set>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "casefile/case_spec.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "tests/case_helpers.hpp"

namespace magfem {
namespace {

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::filesystem::path& path) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

std::set<vtkIdType> used_points(vtkUnstructuredGrid* grid) {
  std::set<vtkIdType> used;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    grid->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      used.insert(ids->GetId(k));
  }
  return used;
}

vtkStringArray* strings(vtkFieldData* data, const char* name) {
  return vtkStringArray::SafeDownCast(data->GetAbstractArray(name));
}

// Types and names common to the 2D and 3D files: ids Int32, each cell's names those of its ids.
void expect_ids_and_names(vtkUnstructuredGrid* grid, const std::vector<std::string>& regions,
                          const std::vector<std::string>& materials) {
  vtkDataArray* region_id = grid->GetCellData()->GetArray("region_id");
  vtkDataArray* material_id = grid->GetCellData()->GetArray("material_id");
  ASSERT_TRUE(region_id && material_id);
  EXPECT_EQ(region_id->GetDataType(), VTK_INT);
  EXPECT_EQ(region_id->GetDataTypeSize(), 4);
  EXPECT_EQ(material_id->GetDataType(), VTK_INT);
  vtkStringArray* region = strings(grid->GetCellData(), "region");
  vtkStringArray* material = strings(grid->GetCellData(), "material");
  vtkStringArray* region_names = strings(grid->GetFieldData(), "region_names");
  vtkStringArray* material_names = strings(grid->GetFieldData(), "material_names");
  ASSERT_TRUE(region && material && region_names && material_names);
  ASSERT_EQ(region_names->GetNumberOfValues(), static_cast<vtkIdType>(regions.size()));
  for (std::size_t i = 0; i < regions.size(); ++i)
    EXPECT_EQ(region_names->GetValue(static_cast<vtkIdType>(i)), regions[i]);
  ASSERT_EQ(material_names->GetNumberOfValues(), static_cast<vtkIdType>(materials.size()));
  for (std::size_t i = 0; i < materials.size(); ++i)
    EXPECT_EQ(material_names->GetValue(static_cast<vtkIdType>(i)), materials[i]);
  ASSERT_EQ(region->GetNumberOfValues(), grid->GetNumberOfCells());
  std::set<int> seen;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const int r = static_cast<int>(region_id->GetComponent(c, 0));
    const int m = static_cast<int>(material_id->GetComponent(c, 0));
    seen.insert(r);
    ASSERT_EQ(region->GetValue(c), r < 0 ? "air" : regions[static_cast<std::size_t>(r)]) << c;
    ASSERT_EQ(material->GetValue(c), materials[static_cast<std::size_t>(m)]) << c;
  }
  EXPECT_EQ(seen.size(), regions.size() + 1) << "every region and the background air";
}

// Magnetized sphere in an open boundary (coarse, order 2): the shell's nodes are a good share
// of all, and none may reach the file.
TEST(VtuOutput, SphereInOpenSpaceKeepsOnlyUsedPointsWithTheirB) {
  const auto run = run_case_3d(read_case_text(test::magnetized_sphere_case3d("4") + R"(
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 8}
solver: {order: 2}
)",
                                              "vtu_sphere.yaml"));
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "vtu_sphere";
  std::filesystem::remove_all(dir);
  write_outputs_3d(*run, dir);
  const auto grid = read_vtu(dir / "solution.vtu");

  // The DOFs of the written (non-shell) tets, counted from the DOF map.
  std::set<int> written_dofs;
  const int per = run->dofs->dofs_per_element();
  for (std::size_t t = 0; t < run->mesh.n_tets(); ++t)
    if (!run->problem.is_shell(t))
      written_dofs.insert(run->dofs->element_dofs(t), run->dofs->element_dofs(t) + per);
  const auto n_shell_only = run->dofs->n_dofs() - static_cast<int>(written_dofs.size());
  std::printf("%d DOFs, %d used only by the shell, %lld points in the file\n", run->dofs->n_dofs(),
              n_shell_only, static_cast<long long>(grid->GetNumberOfPoints()));
  ASSERT_GT(n_shell_only, 100);
  EXPECT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(written_dofs.size()));
  EXPECT_EQ(used_points(grid).size(), static_cast<std::size_t>(grid->GetNumberOfPoints()));

  // B at every file point is the recovered B of the DOF at that point.
  std::map<std::array<double, 3>, int> dof_at;
  const auto& points = run->dofs->dof_points();
  for (int d = 0; d < run->dofs->n_dofs(); ++d)
    dof_at[{points[d].x(), points[d].y(), points[d].z()}] = d;
  const auto b_dof = run->recovered_B.dof_average();
  vtkDataArray* b = grid->GetPointData()->GetArray("B");
  vtkDataArray* phi = grid->GetPointData()->GetArray("phi");
  ASSERT_TRUE(b && phi);
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p) {
    double x[3];
    grid->GetPoint(p, x);
    const auto it = dof_at.find({x[0], x[1], x[2]});
    ASSERT_NE(it, dof_at.end()) << "point " << p;
    ASSERT_TRUE(written_dofs.count(it->second)) << "a shell node kept: point " << p;
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(b->GetComponent(p, k), b_dof[static_cast<std::size_t>(it->second)][k])
          << "point " << p;
    ASSERT_EQ(phi->GetComponent(p, 0), run->field->phi()[it->second]) << "point " << p;
  }
  expect_ids_and_names(grid, {"sphere"}, {"air", "pm"});
}

// A planar case with an open boundary: the same for triangles (A_z, B per point).
TEST(VtuOutput, PlanarOpenBoundaryHasIntIdsNamesAndNoShellNodes) {
  const auto run = run_case_2d(
      read_case_text(test::magnet_and_iron_disks_case2d("steel_1010") + "solver: {order: 2}\n",
                     "vtu_planar.yaml"));
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "vtu_planar";
  std::filesystem::remove_all(dir);
  write_outputs_2d(*run, dir);
  const auto grid = read_vtu(dir / "solution.vtu");
  EXPECT_EQ(used_points(grid).size(), static_cast<std::size_t>(grid->GetNumberOfPoints()));
  EXPECT_LT(grid->GetNumberOfPoints(), run->dofs->n_dofs()) << "the shell's nodes dropped";
  expect_ids_and_names(grid, {"magnet", "iron"}, {"air", "pm", "steel_1010"});
}

} // namespace
} // namespace magfem
