// The command line as a user runs it: every output of `solve` read back and checked against
// the physics (the VTU through VTK), option errors, a solver failure, the analytic model's
// refusals, `compare` on a hand-computed case and parallel sweeps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <nlohmann/json.hpp>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "core/constants.hpp"
#include "materials/bh_table_file.hpp"
#include "materials/material_library.hpp"
#include "tests/case_helpers.hpp"
#include "tests/run_cli.hpp"

namespace fs = std::filesystem;

namespace {

using Outcome = magfem::test::CliOutcome;
Outcome run(const std::string& args) {
  return magfem::test::run_cli(args);
}

fs::path fresh_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / "magfem_tests" / "cli" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A 2D case with nonlinear iron that Newton cannot finish in one iteration.
const std::string nonlinear_case = "title: magnet and nonlinear iron disk\n" +
                                   magfem::test::magnet_and_iron_disks_case2d("steel_1010") +
                                   "solver: {order: 1, max_iterations: 1, tolerance: 1e-12}\n";

// One count of unknowns on the console (issue 34: the progress line said 92090 and the solve
// line 92740): the progress line that sets up the linear solver and the solve line give the
// same number of unknowns, the size of the system solved, which is summary.json's
// free_unknowns; the solve line names the other count DOFs (summary.json's `unknowns`) and
// the difference, the values boundary conditions fix (> 0: every case here has an outer
// boundary). The phrase "free unknowns" is gone: one word for one count.
void expect_one_count_of_unknowns(const std::string& console, const fs::path& summary_file) {
  std::smatch solve, setup;
  ASSERT_TRUE(std::regex_search(
      console, solve,
      std::regex(R"(solve    order \d, (\d+) unknowns \((\d+) DOFs, (\d+) fixed\))")))
      << console;
  ASSERT_TRUE(std::regex_search(
      console, setup,
      std::regex(R"((factorization: CHOLMOD|preconditioner set-up: [a-z ]+), (\d+) unknowns)")))
      << console;
  const long free = std::stol(solve[1]), dofs = std::stol(solve[2]), fixed = std::stol(solve[3]);
  EXPECT_EQ(std::stol(setup[2]), free) << console;
  EXPECT_EQ(dofs - free, fixed);
  EXPECT_GT(fixed, 0);
  EXPECT_EQ(console.find("free unknowns"), std::string::npos) << console;
  const auto j = nlohmann::json::parse(read_text(summary_file));
  EXPECT_EQ(j["free_unknowns"].get<long>(), free);
  EXPECT_EQ(j["unknowns"].get<long>(), dofs);
}

} // namespace

// The diametric cylinder (B_r 1 T, mu_r 1) has B = B_r/2 x_hat inside exactly, and the
// exterior field of a 2D dipole. Every output file is read back: summary.json, the probe
// CSVs and the VTU through VTK's reader.
TEST(Cli, SolveWritesEveryOutputAndTheVtuHoldsTheField) {
  const auto out = fresh_dir("cylinder");
  const auto r = run("solve " + magfem::test::example("2d/diametric_cylinder.yaml") + " --out " +
                     out.string());
  ASSERT_EQ(r.status, 0) << r.out;

  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_FALSE(summary.at("magfem_version").get<std::string>().empty());
  EXPECT_FALSE(summary.at("commit").get<std::string>().empty());
  EXPECT_TRUE(summary.at("converged").get<bool>());
  double interior_area = 0;
  for (const auto& region : summary.at("regions"))
    if (region.at("name") != "exterior (open boundary)")
      interior_area += region.at("area_m2").get<double>();
  for (const char* probe : {"r12.csv", "r5.csv", "x_axis.csv"})
    EXPECT_TRUE(fs::is_regular_file(out / probe)) << probe;
  EXPECT_EQ(read_text(out / "x_axis.csv").substr(0, 10), "x,y,Bx,By\n");

  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((out / "solution.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_GT(grid->GetNumberOfCells(), 1000);
  // The VTU holds every element but the shell's: their areas, computed here from the
  // corner coordinates, add up to the regions' areas in summary.json (straight-sided P2
  // triangles, so only round-off separates the two sums).
  double area = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      grid->GetPoint(grid->GetCell(c)->GetPointId(k), p[k]);
    area += 0.5 * std::abs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                           (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
  }
  EXPECT_NEAR(area, interior_area, 1e-9 * interior_area);

  for (const char* name : {"A_z", "B", "|B|"})
    EXPECT_NE(grid->GetPointData()->GetArray(name), nullptr) << name;
  vtkDataArray* region = grid->GetCellData()->GetArray("region_id");
  vtkDataArray* b = grid->GetCellData()->GetArray("B");
  vtkDataArray* h = grid->GetCellData()->GetArray("H");
  ASSERT_TRUE(region && b && h);
  // Inside the magnet (region 0) B = (0.5, 0) T and H = (B - B_r)/mu0 = (-0.5/mu0, 0). The
  // circle is a polygon (chord tolerance 5 um on 10 mm): its vertices perturb the field of
  // the elements that touch them by up to ~0.5 % (a wedge of 1.6 degrees turning), while the
  // mean over the magnet sees only the polygon's shape error, ~1e-4.
  int magnet_cells = 0;
  double max_deviation = 0, mean_bx = 0, mean_hx = 0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    if (region->GetComponent(c, 0) != 0)
      continue;
    ++magnet_cells;
    max_deviation = std::max(
        {max_deviation, std::abs(b->GetComponent(c, 0) - 0.5), std::abs(b->GetComponent(c, 1))});
    mean_bx += b->GetComponent(c, 0);
    mean_hx += h->GetComponent(c, 0) * magfem::mu0;
  }
  ASSERT_GT(magnet_cells, 100);
  EXPECT_LT(max_deviation, 5e-3);
  EXPECT_NEAR(mean_bx / magnet_cells, 0.5, 5e-4);
  EXPECT_NEAR(mean_hx / magnet_cells, -0.5, 5e-4);
  std::printf("magnet cells %d: max |B - B_exact| %.2e T, mean Bx %.6f T\n", magnet_cells,
              max_deviation, mean_bx / magnet_cells);
}

// The console's "wrote" line names every file the solve left in its folder, forces.csv too
// (issue 34 item 9: it was missing), and nothing it did not write.
TEST(Cli, WroteLineListsEveryFileInTheOutputFolder) {
  const auto out = fresh_dir("wrote_line");
  const fs::path case_file = out.parent_path() / "wrote_line.yaml";
  std::ofstream(case_file) << magfem::test::magnet_and_iron_disks_case2d("steel_1010") +
                                  R"(probes:
  - {name: axis, type: line, start: [-20, 0], end: [20, 0], points: 11}
forces:
  - {name: on_iron, type: circle, center: [6, 0], radius: 5.5}
)";
  const auto r = run("solve " + case_file.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string prefix = "wrote    " + out.string() + "/";
  const auto at = r.out.find(prefix);
  ASSERT_NE(at, std::string::npos) << r.out;
  const auto begin = at + prefix.size();
  std::stringstream listed(r.out.substr(begin, r.out.find('\n', begin) - begin));
  std::set<std::string> named, present;
  for (std::string name; std::getline(listed, name, ',');)
    named.insert(name.substr(name.find_first_not_of(' ')));
  for (const auto& f : fs::directory_iterator(out))
    if (f.path().filename().string()[0] != '.') // the output stage's own marker
      present.insert(f.path().filename().string());
  EXPECT_EQ(named, present) << r.out;
  EXPECT_TRUE(named.count("forces.csv")) << r.out;
}

TEST(Cli, OptionErrorsExitWith2NamingTheOptionAndWriteNothing) {
  const auto out = fresh_dir("options");
  const std::string c = magfem::test::example("2d/diametric_cylinder.yaml");
  const std::string o = " --out " + out.string();
  const std::string s3 = magfem::test::example("3d/two_spheres.yaml");
  const std::array<std::pair<std::string, std::string>, 15> cases{{
      {"solve " + c + o + " --order 3", "--order"},
      {"solve " + c + o + " --order 1.5", "--order"}, // was truncated to 1
      {"solve " + c + o + " --order 0", "--order"},   // was "as in the case", silently
      {"solve " + c + o + " --mesh-scale 0", "--mesh-scale"},
      {"solve " + c + o + " --mesh-scale nan", "--mesh-scale"},
      {"solve " + c + " --out", "--out"},
      {"solve " + c + o + " --frobnicate 2", "--frobnicate"},
      {"solve" + o, "wrong number of arguments"},
      {"sweep " + c + o + " --rotate arm --axis z --angles 0:10:20 --jobs 0", "--jobs"},
      // A planar case moves in its plane, and only groups it has.
      {"sweep " + c + o + " --move magnet --axis x --positions 0,1", "--move"},
      {"sweep " + c + o + " --move magnet --axis z --positions 0,1", "--axis"},
      {"sweep " + s3 + o + " --move arm --rotate arm --axis z --positions 0,1", "not both"},
      {"sweep " + s3 + o + " --move arm --axis z --angles 0,1", "--angles"},
      // An axisymmetric translation has no torque: a --point would be ignored.
      {"sweep " + magfem::test::example("axi/voice_coil_magnet.yaml") + o +
           " --move coil --axis z --positions 0,1 --point 0,0,1",
       "--point"},
      {"transmogrify " + c, "unknown command"},
  }};
  for (const auto& [args, named] : cases) {
    const auto r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(named), std::string::npos) << args << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(out));
}

// Newton stopped at max_iterations is a failure: exit 3, a message, no output directory.
TEST(Cli, NewtonThatDoesNotConvergeExits3AndWritesNothing) {
  const auto out = fresh_dir("newton");
  const auto r = run("solve " + magfem::test::write_temp_case("cli_newton.yaml", nonlinear_case) +
                     " --out " + out.string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("solver failed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

// A small 3D sphere (B_r 1 T) whose CG solve is set from the test: 18k P1 unknowns, ~5 s.
std::string sphere_case(const std::string& solver) {
  return R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: 10, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}}
boundary: {type: open, radius: 25}
mesh: {size: 4}
solver: )" +
         solver + R"(
output: {vtu: false}
probes:
  - {name: centre, type: points, points: [[0, 0, 0]]}
)";
}

// A Krylov solve stopped by its iteration limit is a solver failure, whichever
// preconditioner ran: exit 3, the reason named, no output directory. (GAMG and the
// automatic AMG fallback are covered in tests/solver/test_solver_failures.cpp.)
TEST(Cli, KrylovStoppedByItsIterationLimitExits3AndWritesNothing) {
  for (const std::string pre : {"amg", "ichol"}) {
    const auto out = fresh_dir("krylov_" + pre);
    const std::string solver =
        "{order: 1, linear_solver: cg, preconditioner: " + pre + ", linear_max_iterations: 3}";
    const auto r =
        run("solve " + magfem::test::write_temp_case("cli_krylov.yaml", sphere_case(solver)) +
            " --out " + out.string());
    EXPECT_EQ(r.status, 3) << pre << "\n" << r.out;
    EXPECT_NE(r.out.find("did not converge"), std::string::npos) << pre << "\n" << r.out;
    EXPECT_NE(r.out.find("3 iterations"), std::string::npos) << pre << "\n" << r.out;
    EXPECT_FALSE(fs::exists(out)) << pre;
  }
}

// summary.json says which solver ran and how hard it worked; the console shows the stages
// on stderr unless --quiet, and the Krylov count on the solve line. B at the centre of the
// uniformly magnetized ball is (2/3) B_r z exactly; 3 % covers the coarse P1 mesh (measured
// ~1 %), and it checks that the AMG solution is the field, not just that a solve ran.
TEST(Cli, SolveReportsTheKrylovSolverAndItsProgress) {
  const auto out = fresh_dir("krylov_summary");
  const auto c = magfem::test::write_temp_case("cli_krylov_ok.yaml",
                                               sphere_case("{order: 1, preconditioner: amg}"));
  const auto r = run("solve " + c + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* stage : {"meshing", "assembly", "preconditioner set-up: boomeramg",
                            "solve: CG + boomeramg", "post-processing"})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage << "\n" << r.out;
  EXPECT_NE(r.out.find("cg + boomeramg, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" CG iterations"), std::string::npos) << r.out;
  expect_one_count_of_unknowns(r.out, out / "summary.json");
  const auto j = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(j["linear_solver"], "cg");
  EXPECT_EQ(j["preconditioner"], "boomeramg");
  EXPECT_GT(j["linear_iterations"].get<int>(), 1);
  EXPECT_LT(j["linear_iterations"].get<int>(), 100);
  EXPECT_GE(j["threads"].get<int>(), 1);
  EXPECT_EQ(j["ranks"], 1);
  EXPECT_GT(j["timings_s"]["linear_setup"].get<double>(), 0.0);
  EXPECT_GT(j["timings_s"]["linear_solve"].get<double>(), 0.0);
  const std::string centre = read_text(out / "centre.csv");
  const auto last = centre.substr(centre.find('\n') + 1);
  double x, y, z, bx, by, bz;
  ASSERT_EQ(std::sscanf(last.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &x, &y, &z, &bx, &by, &bz), 6)
      << centre;
  EXPECT_NEAR(bz, 2.0 / 3.0, 0.03 * 2.0 / 3.0);

  fs::remove_all(out);
  const auto quiet = run("solve " + c + " --quiet --out " + out.string());
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find("meshing"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("preconditioner set-up"), std::string::npos) << quiet.out;
}

// A 2D solve shows its stages on stderr like a 3D one (it printed nothing before the
// results), and --quiet silences them. A small magnet disk so that the run takes a second.
TEST(Cli, TwoDimensionalSolveShowsItsStagesUnlessQuiet) {
  const auto c = magfem::test::write_temp_case("cli_progress2d.yaml", R"(unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: magnet, shape: disk, radius: 10, material: pm, magnetization: {type: parallel, angle: 0}}
boundary: {type: open, radius: 25}
mesh: {size: 3}
output: {vtu: false}
probes:
  - {name: r12, type: circle, radius: 12, points: 36}
)");
  const auto out = fresh_dir("progress2d");
  const auto r = run("solve " + c + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* stage : {"meshing", "assembly: ", " triangles, order 2",
                            "factorization: CHOLMOD", "post-processing"})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage << "\n" << r.out;
  expect_one_count_of_unknowns(r.out, out / "summary.json");
  fs::remove_all(out);
  const auto quiet = run("solve " + c + " --quiet --out " + out.string());
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  for (const char* stage : {"meshing", "assembly: ", "factorization", "post-processing"})
    EXPECT_EQ(quiet.out.find(stage), std::string::npos) << stage << "\n" << quiet.out;
}

// `dimension: axisymmetric` (the word the docs use) solves the same case as `dimension: axi`,
// bit for bit: the same energy, inductance and probe file. A misspelling exits 2 naming the
// file, the line and the field, and lists the choices; nothing is written. The axisymmetric
// console gives one count of unknowns too.
TEST(Cli, AxisymmetricIsASpellingOfAxiAndAMisspellingListsTheChoices) {
  const std::string text = read_text(magfem::test::example("axi/solenoid.yaml"));
  const std::string from = "dimension: axi\n";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
  auto respelled = [&](const std::string& word) {
    std::string t = text;
    t.replace(at, from.size(), "dimension: " + word + "\n");
    return magfem::test::write_temp_case("cli_dimension_" + word + ".yaml", t);
  };
  const auto out_axi = fresh_dir("dimension_axi"), out_spelled = fresh_dir("dimension_spelled");
  const auto a = run("solve " + respelled("axi") + " --mesh-scale 3 --out " + out_axi.string());
  ASSERT_EQ(a.status, 0) << a.out;
  expect_one_count_of_unknowns(a.out, out_axi / "summary.json");
  const auto b =
      run("solve " + respelled("axisymmetric") + " --mesh-scale 3 --out " + out_spelled.string());
  ASSERT_EQ(b.status, 0) << b.out;
  const auto ja = nlohmann::json::parse(read_text(out_axi / "summary.json"));
  const auto jb = nlohmann::json::parse(read_text(out_spelled / "summary.json"));
  EXPECT_EQ(jb["dimension"], "axi");
  EXPECT_EQ(jb["unknowns"], ja["unknowns"]);
  EXPECT_EQ(jb["energy_J"].get<double>(), ja["energy_J"].get<double>());
  EXPECT_EQ(jb["coils"][0]["inductance_H"].get<double>(),
            ja["coils"][0]["inductance_H"].get<double>());
  EXPECT_EQ(read_text(out_spelled / "axis.csv"), read_text(out_axi / "axis.csv"));

  const auto typo_out = fresh_dir("dimension_typo");
  const auto typo_case = respelled("axisymetric");
  const auto bad = run("solve " + typo_case + " --out " + typo_out.string());
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find(typo_case + ":" + std::to_string(line)), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("dimension"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("2 | 3 | axi | axisymmetric (got 'axisymetric')"), std::string::npos)
      << bad.out;
  EXPECT_FALSE(fs::exists(typo_out));
}

// A sweep reports each finished position on stderr; --quiet silences that too (it did not).
TEST(Cli, SweepShowsItsPositionsUnlessQuiet) {
  const std::string c = magfem::test::example("axi/voice_coil_magnet.yaml");
  const std::string sweep = "sweep " + c + " --move coil --axis z --positions 0,6 --mesh-scale 3";
  const auto out = fresh_dir("sweep_progress");
  const auto r = run(sweep + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("2/2"), std::string::npos) << r.out;
  fs::remove_all(out);
  const auto quiet = run(sweep + " --quiet --out " + out.string());
  ASSERT_EQ(quiet.status, 0) << quiet.out;
  EXPECT_EQ(quiet.out.find("1/2"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("2/2"), std::string::npos) << quiet.out;
}

// The analytic models have no nonlinear iron: refused with exit 2, the region named.
TEST(Cli, AnalyticRefusesNonlinearIronNamingTheRegion) {
  const auto out = fresh_dir("analytic_refusal");
  const auto r = run("analytic " +
                     magfem::test::write_temp_case("cli_analytic.yaml", R"(dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: 5, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}}
  - {name: yoke, shape: box, size: [10, 10, 4], material: steel_1010,
     placement: {translate: [0, 0, 12]}}
boundary: {type: open, radius: 40}
mesh: {size: 8}
probes:
  - {name: axis, type: line, start: [0, 0, 6], end: [0, 0, 9], points: 4}
)") + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("yoke"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

// Reference Bx = +-1 (rms 1); test Bx = +-1 + 0.1 alternating to 1.1 / -0.9: rms(test) =
// sqrt((1.21 + 0.81)/2), eq. 3.117 = (1 - rms_test)/1 = -0.4988 %, pointwise rms error =
// rms(0.1) = 10 %, max difference 0.1 T. By is 1 against a reference of 2 everywhere:
// eq. 3.117 = (2 - 1)/2 = 50 %, pointwise 50 %.
TEST(Cli, CompareReportsEquation3117AndThePointwiseErrorOfAHandComputedCase) {
  const auto dir = fresh_dir("compare");
  fs::create_directories(dir);
  // Bz is zero in the reference (as B_phi of an axisymmetric field): no percentage, the
  // absolute differences only (it printed -275731 % on a sphere before).
  std::ofstream(dir / "ref.csv")
      << "x,y,Bx,By,Bz\n0,0,1,2,0\n1,0,-1,2,0\n2,0,1,2,1e-18\n3,0,-1,2,0\n";
  std::ofstream(dir / "test.csv")
      << "x,y,Bx,By,Bz\n0,0,1.1,1,0.002\n1,0,-0.9,1,0\n2,0,1.1,1,0\n3,0,-0.9,1,0\n";
  const auto r = run("compare " + (dir / "ref.csv").string() + " " + (dir / "test.csv").string());
  ASSERT_EQ(r.status, 0) << r.out;
  auto row = [&](const std::string& comp) {
    std::istringstream lines(r.out);
    std::string line;
    while (std::getline(lines, line))
      if (line.rfind(comp + " ", 0) == 0) {
        std::istringstream f(line.substr(comp.size()));
        std::array<double, 5> v{};
        for (auto& x : v)
          f >> x;
        return v;
      }
    ADD_FAILURE() << "no row " << comp << " in\n" << r.out;
    return std::array<double, 5>{};
  };
  const auto bx = row("Bx");
  EXPECT_NEAR(bx[0], 1.0, 1e-5);
  EXPECT_NEAR(bx[1], std::sqrt(1.01), 1e-5);
  EXPECT_NEAR(bx[2], 100 * (1 - std::sqrt(1.01)), 1e-3);
  EXPECT_NEAR(bx[3], 10.0, 1e-3);
  EXPECT_NEAR(bx[4], 0.1, 1e-6);
  const auto by = row("By");
  EXPECT_NEAR(by[2], 50.0, 1e-3);
  EXPECT_NEAR(by[3], 50.0, 1e-3);
  std::istringstream lines(r.out);
  std::string line, bz;
  while (std::getline(lines, line))
    if (line.rfind("Bz ", 0) == 0)
      bz = line;
  std::istringstream f(bz.substr(2));
  std::string rms_ref, rms_test, eq3117, pointwise;
  double max_diff = 0, rms_diff = 0;
  f >> rms_ref >> rms_test >> eq3117 >> pointwise >> max_diff >> rms_diff;
  EXPECT_EQ(eq3117, "n/a") << bz;
  EXPECT_EQ(pointwise, "n/a") << bz;
  EXPECT_NEAR(max_diff, 0.002, 1e-9) << bz;
  EXPECT_NEAR(rms_diff, 0.001, 1e-9) << bz; // sqrt(0.002^2 / 4)

  std::ofstream(dir / "short.csv") << "x,y,Bx,By\n0,0,1,2\n";
  const auto mismatch =
      run("compare " + (dir / "ref.csv").string() + " " + (dir / "short.csv").string());
  EXPECT_EQ(mismatch.status, 2) << mismatch.out;
}

// Positions are independent, so the number of worker threads cannot change the numbers.
TEST(Cli, ParallelSweepEqualsTheSerialOne) {
  const std::string c = magfem::test::example("3d/two_spheres.yaml");
  const std::string sweep = "sweep " + c + " --rotate arm --axis y --angles 0:30:150 --analytic";
  const auto one = fresh_dir("sweep1"), two = fresh_dir("sweep2");
  ASSERT_EQ(run(sweep + " --jobs 1 --out " + one.string()).status, 0);
  ASSERT_EQ(run(sweep + " --jobs 2 --out " + two.string()).status, 0);
  const std::string serial = read_text(one / "sweep.csv");
  EXPECT_EQ(std::count(serial.begin(), serial.end(), '\n'), 7); // header + 6 angles
  EXPECT_EQ(serial, read_text(two / "sweep.csv"));
}

// A 3D translation: sweep.csv and summary.json name the position in mm, and the analytic
// force along the line of centres falls as the dipole-dipole force, 1/d^4 (14 -> 20 mm:
// (14/20)^4 = 0.2401 of the first).
TEST(Cli, SweepTranslatingA3DGroupReportsPositionsInMillimetres) {
  const auto out = fresh_dir("sweep_translate");
  const auto r = run("sweep " + magfem::test::example("3d/two_spheres.yaml") +
                     " --move arm --axis z --positions 0,6 --analytic --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string csv = read_text(out / "sweep.csv");
  EXPECT_EQ(csv.rfind("position_mm,Tx,Ty,Tz,Fx,Fy,Fz\n0,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\n6,"), std::string::npos) << csv;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary.at("motion"), "translate");
  EXPECT_EQ(summary.at("positions").at(1).at("position_mm"), 6.0);
  std::istringstream rows(csv);
  std::string line;
  std::getline(rows, line);
  std::vector<double> fx;
  while (std::getline(rows, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');)
      v.push_back(std::stod(cell));
    fx.push_back(v.at(4));
  }
  ASSERT_EQ(fx.size(), 2u);
  EXPECT_NEAR(fx[1] / fx[0], std::pow(14.0 / 20.0, 4), 1e-5);
}

// Rotated about (0, 0, 7) mm, the small sphere sits inside the large one at 180 degrees: that
// position fails (no air sphere separates the group), the 0-degree one is kept and listed.
TEST(Cli, SweepWithAFailingPositionExits3AndKeepsTheOthers) {
  const auto out = fresh_dir("sweep_fail");
  const auto r = run("sweep " + magfem::test::example("3d/two_spheres.yaml") +
                     " --rotate arm --axis y --point 0,0,7 --angles 0,180 --mesh-scale 4 --out " +
                     out.string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("1 of 2 positions failed"), std::string::npos) << r.out;
  const std::string csv = read_text(out / "sweep.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2) << csv; // header + the 0-degree row
  EXPECT_EQ(csv.find("\n180,"), std::string::npos) << csv;
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary.at("failed_positions"), 1);
  const auto& failed = summary.at("positions").at(1);
  EXPECT_EQ(failed.at("angle_deg"), 180.0);
  EXPECT_FALSE(failed.at("ok").get<bool>());
  EXPECT_NE(failed.at("error").get<std::string>().find("not separated"), std::string::npos);
}

// --param sets a case-file parameter for solve and analytic: a ball of radius ${a} (B_r 1 T)
// and a probe at z = 7 mm, inside the ball as written (a = 10: B_z = 2/3 T exactly) and, with
// --param a=5, 2 mm outside it on the axis (the dipole field 2/3 (5/7)^3 T = 0.243 T). A
// --param that the run ignored would read 2/3. The FE tolerance, 3 %, is the P2 field 2 mm
// from a 4 mm mesh's curved magnet surface (measured below 1 %); the charge model's 1e-4 is
// its cubature tolerance.
TEST(Cli, ParamSetsACaseParameterForSolveAndAnalytic) {
  const std::string text = R"(dimension: 3
unit: mm
parameters: {a: 10}
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: ball, shape: spherical_segment, r_outer: ${a}, material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}}
boundary: {type: open, radius: 25}
mesh: {size: 4}
solver: {order: 2}
output: {vtu: false}
probes:
  - {name: axis, type: points, points: [[0, 0, 7]]}
)";
  const std::string c = magfem::test::write_temp_case("cli_param.yaml", text);
  auto bz_at_probe = [](const fs::path& dir) {
    std::ifstream in(dir / "axis.csv");
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    std::vector<std::string> names, values;
    for (std::stringstream h(header); std::getline(h, names.emplace_back(), ',');) {
    }
    for (std::stringstream r(row); std::getline(r, values.emplace_back(), ',');) {
    }
    for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
      if (names[k] == "Bz")
        return std::stod(values[k]);
    ADD_FAILURE() << "no Bz in " << header;
    return 0.0;
  };
  const double inside = 2.0 / 3.0, outside = 2.0 / 3.0 * std::pow(5.0 / 7.0, 3);
  const auto an10 = fresh_dir("param_an10"), an5 = fresh_dir("param_an5"),
             fe5 = fresh_dir("param_fe5");
  ASSERT_EQ(run("analytic " + c + " --out " + an10.string()).status, 0);
  const auto r = run("analytic " + c + " --param a=5 --out " + an5.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NEAR(bz_at_probe(an10), inside, 1e-4 * inside);
  EXPECT_NEAR(bz_at_probe(an5), outside, 1e-4 * outside);
  const auto s = run("solve " + c + " --param a=5 --quiet --out " + fe5.string());
  ASSERT_EQ(s.status, 0) << s.out;
  EXPECT_NEAR(bz_at_probe(fe5), outside, 0.03 * outside);
  // A name the file does not declare, or no value: exit 2 naming --param, nothing written.
  const auto bad = fresh_dir("param_bad");
  for (const std::string p : {"b=5", "a", "=5", "a=five"}) {
    const auto e = run("solve " + c + " --param " + p + " --out " + bad.string());
    EXPECT_EQ(e.status, 2) << p << "\n" << e.out;
    EXPECT_NE(e.out.find("--param"), std::string::npos) << p << "\n" << e.out;
  }
  EXPECT_FALSE(fs::exists(bad));
}

// `magfem materials --export NAME` writes what `bh_file:` reads: every bundled curve comes back
// bit for bit (a lossy number format or a missing origin row would fail); a magnet or an
// unknown name is refused naming --export.
TEST(Cli, MaterialsExportReadsBackAsTheLibraryCurve) {
  const fs::path dir = fs::temp_directory_path() / "magfem_tests" / "materials_export";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto& lib = magfem::MaterialLibrary::bundled();
  for (const auto& name : lib.names()) {
    const auto& curve = lib.find(name)->curve;
    if (!curve)
      continue;
    const fs::path csv = dir / (name + ".csv");
    const Outcome o =
        magfem::test::run_command(std::string(magfem::test::magfem_binary()) +
                                  " materials --export " + name + " > " + csv.string());
    ASSERT_EQ(o.status, 0) << o.out;
    const auto rows = magfem::read_bh_table_file(csv.string(), "");
    EXPECT_EQ(rows.h_Apm, curve->h_table()) << name;
    EXPECT_EQ(rows.b_T, curve->b_table()) << name;
  }
  for (const char* bad : {"N42", "unobtainium"}) {
    const Outcome o = magfem::test::run_cli(std::string("materials --export ") + bad);
    EXPECT_EQ(o.status, 2) << o.out;
    EXPECT_NE(o.out.find("--export"), std::string::npos) << o.out;
  }
  const Outcome list = magfem::test::run_cli("materials");
  EXPECT_EQ(list.status, 0);
  EXPECT_NE(list.out.find("steel_1010    soft"), std::string::npos) << list.out;
}

// `magfem materials` shows the knee data the demagnetization check uses: the listing gives a
// magnet's H_cJ (kA/m) and its coefficient, or says it has none; `magfem materials N42` its
// knee at 20..150 C, checked here against B_r(T) - mu0 mu_r H_cJ(T) evaluated from the
// library's 20 C numbers and coefficients (printed to 1 mT: tolerance 0.5 mT), and its source.
TEST(Cli, MaterialsShowsAMagnetGradesKneeData) {
  const Outcome list = magfem::test::run_cli("materials");
  ASSERT_EQ(list.status, 0) << list.out;
  EXPECT_NE(list.out.find("N42           magnet  B_r 1.31 T, H_cJ 955 kA/m (-0.75 %/K)\n"),
            std::string::npos)
      << list.out;
  EXPECT_NE(list.out.find("ferrite_Y30   magnet  B_r 0.39 T, no knee data"), std::string::npos)
      << list.out;

  const Outcome one = magfem::test::run_cli("materials N42");
  ASSERT_EQ(one.status, 0) << one.out;
  const magfem::Material& n42 = *magfem::MaterialLibrary::bundled().find("N42");
  EXPECT_NE(one.out.find("H_cJ   955 kA/m at 20 C, -0.75 %/K"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("  source " + n42.source), std::string::npos) << one.out;
  EXPECT_NE(n42.source.find("Arnold"), std::string::npos);
  int rows = 0;
  for (const double T : {20.0, 60.0, 80.0, 100.0, 120.0, 150.0}) {
    char label[32];
    std::snprintf(label, sizeof label, "%5.0f C", T);
    const auto at = one.out.find(label);
    ASSERT_NE(at, std::string::npos) << label << "\n" << one.out;
    const double printed = std::stod(one.out.substr(at + std::strlen(label)));
    const double dT = T - 20;
    const double br = 1.31 * (1 - 0.12e-2 * dT), hcj = 955e3 * (1 - 0.75e-2 * dT);
    EXPECT_NEAR(printed, br - magfem::mu0 * 1.11 * hcj, 5e-4) << label;
    ++rows;
  }
  EXPECT_EQ(rows, 6);

  const Outcome none = magfem::test::run_cli("materials ferrite");
  ASSERT_EQ(none.status, 0) << none.out;
  EXPECT_NE(none.out.find("H_cJ   unknown: the demagnetization check reports knee_T null"),
            std::string::npos)
      << none.out;
  const Outcome slip = magfem::test::run_cli("materials M19");
  EXPECT_EQ(slip.status, 2) << slip.out;
  EXPECT_NE(slip.out.find("unknown library material 'M19' (did you mean 'M-19'?)"),
            std::string::npos)
      << slip.out;
}
