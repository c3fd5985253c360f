// Tests of the 3D postprocessing on structured box meshes (no TetGen): field evaluation and
// recovery reproduce a potential the P2 space contains, point location, the probe CSV
// contracts (columns, order, spherical components), energy of uniform fields, VTU export.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "../solver/structured_mesh3d.hpp"
#include "box_field3d.hpp"
#include "core/constants.hpp"
#include "postproc/energy3d.hpp"
#include "postproc/field3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "postproc/recovered_b3d.hpp"
#include "postproc/vtu_export3d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;

using test::h_exact;
using test::phi_exact;

// The box of box_field3d.hpp holding phi_exact.
struct BoxField : test::BoxField3D {
  explicit BoxField(int order, bool regions = false) : BoxField3D(order, regions, phi_exact) {}
};

TEST(Field3D, P2FieldAndRecoveryAreExactForQuadraticPotential) {
  BoxField box(2);
  const PointLocator3D locator(box.mesh);
  const double scale = 1e4;
  const std::vector<Eigen::Vector3d> points = {Eigen::Vector3d(1.1e-3, -2.3e-3, 0.7e-3),
                                               Eigen::Vector3d(-4.9e-3, 4.2e-3, -3.3e-3),
                                               Eigen::Vector3d(0, 0, 0)};
  for (const Eigen::Vector3d& x : points) {
    const auto loc = locator.locate(x);
    ASSERT_TRUE(loc.has_value());
    EXPECT_LT((box.field->point(loc->tet, loc->bary) - x).norm(), 1e-15);
    for (double b : loc->bary)
      EXPECT_GE(b, -1e-12);
    EXPECT_NEAR(box.field->potential(loc->tet, loc->bary), phi_exact(x), 1e-9 * scale);
    EXPECT_LT((box.field->H(loc->tet, loc->bary) - h_exact(x)).norm(), 1e-9 * scale);
    EXPECT_LT((box.field->B(loc->tet, loc->bary) - mu0 * h_exact(x)).norm(), 1e-9 * mu0 * scale);
  }
  // B is linear per element, so averaging exact nodal values is exact.
  const auto rec = RecoveredB3D(*box.field).dof_average();
  for (int d = 0; d < box.dofs->n_dofs(); d += 17)
    EXPECT_LT((rec[d] - mu0 * h_exact(box.dofs->dof_points()[d])).norm(), 1e-9 * mu0 * scale);
  EXPECT_FALSE(locator.locate(Eigen::Vector3d(6, 0, 0) * mm).has_value());
}

// The locator over the probe points' box only (PointLocator3D(mesh, points)) against the
// whole-mesh one: every point gets the same tet and the same barycentric coordinates, bit for
// bit (a containing tet reaches into the box, and the tets are visited in the same order).
// The mesh is cut at x = 0 (a symmetry plane), and half the points lie beyond it:
// they are found at their mirror image, so the box must be the folded points' box. Would
// fail on: the points not folded (their box misses the tets that hold their images), or
// only the tets inside the box kept (those across its edge lost).
TEST(PointLocator3D, OverTheProbePointsBoxFindsWhatTheWholeMeshLocatorFinds) {
  Mesh3D mesh = test::structured_box({0, 0, 0}, {10 * mm, 10 * mm, 10 * mm}, 8);
  mesh.symmetry = {SymmetryPlane3D{0, SymmetryField::normal}};
  std::vector<Eigen::Vector3d> points;
  // Two balls: one by the plane on the kept side, one beyond it whose image lies farther in.
  for (int i = 0; i < 300; ++i) {
    const double a = 0.37 * i, b = 0.11 * i, r = i % 2 ? 1 * mm : 0.5 * mm;
    const double x = i % 2 ? -3 * mm : 1.5 * mm;
    points.emplace_back(x + r * std::cos(a) * std::sin(b), 5 * mm + r * std::sin(a) * std::sin(b),
                        5 * mm + r * std::cos(b));
  }
  const PointLocator3D whole(mesh), near(mesh, points);
  int mirrored = 0;
  for (const Eigen::Vector3d& x : points) {
    const auto a = whole.locate(x), b = near.locate(x);
    ASSERT_TRUE(a.has_value());
    ASSERT_TRUE(b.has_value()) << "x = " << x.transpose();
    EXPECT_EQ(a->tet, b->tet);
    EXPECT_EQ(a->bary, b->bary);
    EXPECT_EQ(a->b_map, b->b_map);
    mirrored += x.x() < 0;
  }
  EXPECT_EQ(mirrored, 150);
}

TEST(Field3D, MaterialLawsAndMagnetization) {
  BoxField box(1, true);
  for (std::size_t t = 0; t < box.mesh.n_tets(); t += 11) {
    const Eigen::Vector3d x = box.field->point(t, {0.25, 0.25, 0.25, 0.25});
    const Eigen::Vector3d h = box.field->H(t, {0.25, 0.25, 0.25, 0.25});
    const Eigen::Vector3d b = box.field->B_of_H(t, x, h);
    const int part = box.mesh.tet_part[t];
    if (part == 0) { // magnet: mu0 mu_r H + B_r x_hat, M0 = B_r / mu0
      EXPECT_LT((b - (mu0 * 1.1 * h + Eigen::Vector3d::UnitX())).norm(), 1e-12);
      EXPECT_NEAR(box.field->magnetization(t, x).x(), 1.0 / mu0, 1e-6);
    } else {
      EXPECT_LT((b - mu0 * (part == 1 ? 10.0 : 1.0) * h).norm(), 1e-12);
      EXPECT_EQ(box.field->magnetization(t, x).norm(), 0.0);
    }
  }
}

// Magnet (z < 0), iron (mu_r 10, z > 0, x < 0) and air: with the quadratic potential, H is
// continuous and the element B linear and continuous inside each region, but B jumps across
// the region boundaries (mu_r, remanence). Recovery per region reproduces it at every point,
// next to the boundaries too; a point on a boundary is read in its tet's region.
TEST(RecoveredB3D, ExactPerRegionForFieldsLinearInEachRegion) {
  BoxField box(2, true);
  const RecoveredB3D rec(*box.field);
  const PointLocator3D locator(box.mesh);
  std::size_t boundary_dofs = 0, slots = 0;
  for (int d = 0; d < box.dofs->n_dofs(); ++d) {
    EXPECT_GE(rec.n_regions_at(d), 1);
    boundary_dofs += rec.n_regions_at(d) > 1;
    slots += rec.n_regions_at(d);
  }
  EXPECT_GT(boundary_dofs, 0u);
  EXPECT_EQ(rec.n_slots(), slots);
  const double scale = 1e4 * mu0 * 10; // |B| in the iron, T
  for (double z : {-4.9, -0.3, -1e-9, 0.0, 1e-9, 0.2, 3.3})
    for (double x : {-4.1, -0.25, 0.0, 0.25, 2.2}) {
      const Eigen::Vector3d p = Eigen::Vector3d(x, 0.37 * x + 0.1, z) * mm;
      const auto loc = locator.locate(p);
      ASSERT_TRUE(loc.has_value());
      EXPECT_LT((rec.at(loc->tet, loc->bary) - box.field->B(loc->tet, loc->bary)).norm(),
                1e-9 * scale)
          << "at (" << x << ", " << z << ") mm, region " << box.mesh.tet_part[loc->tet];
    }
  // One value a DOF (VTU point data): a DOF inside a region keeps that region's value; the
  // regions are averaged only where they meet.
  const auto avg = rec.dof_average();
  for (std::size_t t = 0; t < box.mesh.n_tets(); ++t)
    for (int i = 0; i < box.dofs->dofs_per_element(); ++i)
      if (const int d = box.dofs->element_dofs(t)[i]; rec.n_regions_at(d) == 1) {
        EXPECT_EQ(avg[d], rec.value(d, box.mesh.tet_part[t]));
      }
  EXPECT_THROW(rec.value(0, 7), std::out_of_range);
}

// The recovery's per-tet peak |B| (what the energy summary takes) is the max of |B| at the
// tet's DOF nodes computed directly, bit for bit, and the summary is the same with or without
// it. (The peak taken of vol * B, planted, fails both; seen, removed.)
TEST(RecoveredB3D, ElementPeakBIsTheNodalMaximumOfTheElementField) {
  BoxField box(2, true);
  const RecoveredB3D rec(*box.field);
  ASSERT_EQ(rec.element_peak_B().size(), box.mesh.n_tets());
  for (std::size_t t = 0; t < box.mesh.n_tets(); ++t) {
    double peak = 0;
    for (int i = 0; i < box.dofs->dofs_per_element(); ++i)
      peak = std::max(peak, box.field->B_at_node(t, i).norm());
    ASSERT_EQ(rec.element_peak_B()[t], peak) << "tet " << t;
  }
  const EnergySummary3D direct = summarize_energy_3d(*box.field, {"magnet", "iron"});
  const EnergySummary3D shared =
      summarize_energy_3d(*box.field, {"magnet", "iron"}, &rec.element_peak_B());
  EXPECT_EQ(shared.total_J, direct.total_J);
  for (std::size_t i = 0; i < direct.regions.size(); ++i) {
    EXPECT_EQ(shared.regions[i].peak_B_T, direct.regions[i].peak_B_T) << i;
    EXPECT_EQ(shared.regions[i].energy_J, direct.regions[i].energy_J) << i;
  }
}

TEST(Probes3D, CsvContractsAndSphericalComponents) {
  BoxField box(2);
  const PointLocator3D locator(box.mesh);
  ProbeSpec sphere;
  sphere.name = "s";
  sphere.kind = ProbeSpec::Kind::sphere;
  sphere.center = Eigen::Vector3d(0.5, -0.5, 0.2) * mm;
  sphere.radius = 3 * mm;
  sphere.theta_min = 10 * deg_to_rad;
  sphere.theta_max = 90 * deg_to_rad;
  sphere.phi_min = 0;
  sphere.phi_max = 90 * deg_to_rad;
  sphere.theta_steps = 5;
  sphere.phi_steps = 4;
  const ProbeTable t = sample_probe_3d(*box.field, locator, sphere, mm);
  EXPECT_EQ(t.to_csv().substr(0, t.to_csv().find('\n')),
            "theta_deg,phi_deg,x,y,z,Bx,By,Bz,Brho,Btheta,Bphi,region_id");
  ASSERT_EQ(t.rows.size(), 20u);
  // theta outer loop, phi inner loop, inclusive ranges
  EXPECT_DOUBLE_EQ(t.rows[0][0], 10);
  EXPECT_DOUBLE_EQ(t.rows[3][1], 90);
  EXPECT_DOUBLE_EQ(t.rows[4][0], 30);
  EXPECT_NEAR(t.rows[19][0], 90, 1e-12);
  for (const auto& row : t.rows) {
    const double th = row[0] * deg_to_rad, ph = row[1] * deg_to_rad;
    const Eigen::Vector3d x(row[2], row[3], row[4]); // mm
    const Eigen::Vector3d e_r(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                              std::cos(th));
    EXPECT_LT((x - (sphere.center / mm + 3 * e_r)).norm(), 1e-12);
    const Eigen::Vector3d b(row[5], row[6], row[7]);
    EXPECT_LT((b - mu0 * h_exact(x * mm)).norm(), 1e-12);
    const Eigen::Vector3d e_t(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph),
                              -std::sin(th));
    const Eigen::Vector3d e_p(-std::sin(ph), std::cos(ph), 0);
    EXPECT_NEAR(row[8], b.dot(e_r), 1e-15);
    EXPECT_NEAR(row[9], b.dot(e_t), 1e-15);
    EXPECT_NEAR(row[10], b.dot(e_p), 1e-15);
    EXPECT_NEAR(std::hypot(row[8], row[9], row[10]), b.norm(), 1e-14);
  }

  ProbeSpec line;
  line.name = "l";
  line.start = Eigen::Vector3d(-4, -4, -4) * mm;
  line.end = Eigen::Vector3d(4, 2, 0) * mm;
  line.points = 5;
  const ProbeTable tl = sample_probe_3d(*box.field, locator, line, mm);
  EXPECT_EQ(tl.columns, (std::vector<std::string>{"x", "y", "z", "Bx", "By", "Bz", "region_id"}));
  EXPECT_EQ(tl.rows[0][6], 0); // the box is one region, part 0
  ASSERT_EQ(tl.rows.size(), 5u);
  EXPECT_DOUBLE_EQ(tl.rows[4][1], 2);
  EXPECT_DOUBLE_EQ(tl.rows[2][0], 0);

  ProbeSpec pts;
  pts.name = "p";
  pts.kind = ProbeSpec::Kind::points;
  pts.point_list = {Eigen::Vector3d(1, 2, 3) * mm, Eigen::Vector3d(-1, 0, 4) * mm};
  const RecoveredB3D rec(*box.field);
  const ProbeTable tp = sample_probe_3d(*box.field, locator, pts, mm, &rec);
  ASSERT_EQ(tp.rows.size(), 2u);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(tp.rows[1][3 + k], mu0 * h_exact(pts.point_list[1])[k], 1e-12);

  pts.point_list.push_back(Eigen::Vector3d(0, 0, 9) * mm);
  EXPECT_THROW(sample_probe_3d(*box.field, locator, pts, mm), std::runtime_error);
}

// Uniform H = -grad(-H0 z) in a box of air, iron (mu_r 10) and magnet (mu_r 1.1): energy
// density mu |H|^2 / 2 per region (magnets from the remanent state), peak |B| per law.
TEST(Energy3D, UniformFieldEnergyPerRegion) {
  BoxField box(2, true);
  const double h0 = 1e4;
  Eigen::VectorXd phi(box.dofs->n_dofs());
  for (int d = 0; d < box.dofs->n_dofs(); ++d)
    phi[d] = -h0 * box.dofs->dof_points()[d].z();
  const Field3D field(box.problem, *box.dofs, phi);
  const EnergySummary3D e = summarize_energy_3d(field, {"magnet", "iron"});
  ASSERT_EQ(e.regions.size(), 4u);
  const double v_box = 1e-6;
  EXPECT_NEAR(e.regions[0].volume_m3, v_box / 2, 1e-15);
  EXPECT_NEAR(e.regions[0].energy_J, 0.5 * mu0 * 1.1 * h0 * h0 * v_box / 2, 1e-12);
  EXPECT_NEAR(e.regions[1].energy_J, 0.5 * mu0 * 10 * h0 * h0 * v_box / 4, 1e-12);
  EXPECT_NEAR(e.regions[2].energy_J, 0.5 * mu0 * h0 * h0 * v_box / 4, 1e-12);
  EXPECT_NEAR(e.regions[0].peak_B_T, std::hypot(1.0, mu0 * 1.1 * h0), 1e-12);
  EXPECT_NEAR(e.regions[1].peak_B_T, mu0 * 10 * h0, 1e-12);
  EXPECT_NEAR(e.total_J, e.regions[0].energy_J + e.regions[1].energy_J + e.regions[2].energy_J,
              1e-15);
}

TEST(VtuExport3D, QuadraticTetsWithAllArrays) {
  BoxField box(2, true);
  const auto rec = RecoveredB3D(*box.field).dof_average();
  const VtuGrid g =
      make_vtu_3d(*box.field, rec, {0, 1}, 2, {"magnet", "iron", "air"}, {"pm", "core"});
  EXPECT_EQ(g.points.size(), static_cast<std::size_t>(box.dofs->n_dofs()));
  EXPECT_EQ(g.cell_types.size(), box.mesh.n_tets());
  EXPECT_EQ(g.cell_types[0], 24);
  EXPECT_EQ(g.connectivity.size(), 10 * box.mesh.n_tets());
  // VTK quadratic tet: node 4 is the midpoint of vertices 0 and 1, node 9 of 2 and 3.
  const auto& c = g.connectivity;
  EXPECT_LT((g.points[c[4]] - 0.5 * (g.points[c[0]] + g.points[c[1]])).norm(), 1e-15);
  EXPECT_LT((g.points[c[9]] - 0.5 * (g.points[c[2]] + g.points[c[3]])).norm(), 1e-15);
  ASSERT_EQ(g.cell_data.size(), 6u);
  EXPECT_EQ(g.cell_data[5].name, "magnetization");
  EXPECT_EQ(g.cell_data[5].values.size(), 3 * box.mesh.n_tets());
  EXPECT_EQ(g.point_data[0].name, "phi");
  const auto path = std::filesystem::temp_directory_path() / "magfem_test_vtu3d.vtu";
  write_vtu(path.string(), g);
  // Read back through VTK: what ParaView will see is what was meant to be written.
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkUnstructuredGrid* ug = reader->GetOutput();
  ASSERT_EQ(ug->GetNumberOfCells(), static_cast<vtkIdType>(box.mesh.n_tets()));
  ASSERT_EQ(ug->GetNumberOfPoints(), static_cast<vtkIdType>(g.points.size()));
  EXPECT_EQ(ug->GetCellType(0), 24);
  // Every value the same bits as written (the writer's encoding is raw appended binary; an
  // encoding that rounds fails here: Float64 arrays written as vtkFloatArray, planted, seen to
  // fail, removed).
  for (std::size_t p = 0; p < g.points.size(); ++p) {
    double x[3];
    ug->GetPoint(static_cast<vtkIdType>(p), x);
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(x[k], g.points[p][k]) << "point " << p;
  }
  // Every cell's points in the order written (VTK's cell arrays are filled in bulk: planted,
  // the connectivity read one entry on, seen to fail).
  for (std::size_t c = 0, begin = 0; c < g.offsets.size(); begin = g.offsets[c++]) {
    vtkNew<vtkIdList> ids;
    ug->GetCellPoints(static_cast<vtkIdType>(c), ids);
    ASSERT_EQ(ids->GetNumberOfIds(), static_cast<vtkIdType>(g.offsets[c] - begin)) << "cell " << c;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      ASSERT_EQ(ids->GetId(k), g.connectivity[begin + k]) << "cell " << c;
  }
  for (const auto& array : g.point_data) {
    vtkDataArray* read = ug->GetPointData()->GetArray(array.name.c_str());
    ASSERT_NE(read, nullptr) << array.name;
    ASSERT_EQ(read->GetNumberOfComponents(), array.components) << array.name;
    for (std::size_t i = 0; i < array.values.size(); ++i)
      ASSERT_EQ(read->GetComponent(i / array.components, i % array.components), array.values[i])
          << array.name << " value " << i;
  }
  for (const auto& array : g.cell_data) {
    vtkDataArray* read = ug->GetCellData()->GetArray(array.name.c_str());
    ASSERT_NE(read, nullptr) << array.name;
    for (std::size_t i = 0; i < array.values.size(); ++i)
      ASSERT_EQ(read->GetComponent(i / array.components, i % array.components), array.values[i])
          << array.name << " value " << i;
  }
  std::filesystem::remove(path);
}

} // namespace
} // namespace magfem
