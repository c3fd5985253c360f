// Accuracy study of the magnetized sphere (not a test): prints unknowns, stage times and the
// error of B inside (r = 6 mm) and on the r12 sphere, for the element field and the recovered
// (nodal-averaged) field, against the exact solution. Usage:
//   magfem_sphere3d_study [order=2] [size_scale=1] [chord_tolerance_mm=0.02] [probe_size_mm=1]
//                         [solver=cg|cholmod|automatic]
#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/resource.h>

#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "sphere_cases3d.hpp"

using namespace magfem;

namespace {

void report(const char* label, const ProbeTable& t, double (*scale)(const Eigen::Vector3d&)) {
  double se = 0, sr = 0, me = 0, mr = 0;
  for (const auto& row : t.rows) {
    const Eigen::Vector3d x(row[2], row[3], row[4]), b(row[5], row[6], row[7]);
    const Eigen::Vector3d e = test::sphere_exact_B(x * 1e-3, 10 * test::mm, 1.0);
    se += (b - e).squaredNorm();
    sr += e.squaredNorm();
    me = std::max(me, (b - e).norm());
    mr = std::max(mr, scale(e));
  }
  std::printf("  %-22s rms %.3f%%  max %.3f%%\n", label, 100 * std::sqrt(se / sr), 100 * me / mr);
}

double norm_of(const Eigen::Vector3d& e) {
  return e.norm();
}

ProbeSpec sphere_probe(double r, int n) {
  ProbeSpec p;
  p.name = "r";
  p.kind = ProbeSpec::Kind::sphere;
  p.radius = r;
  p.theta_max = pi;
  p.phi_max = 2 * pi;
  p.theta_steps = n;
  p.phi_steps = 2 * n;
  return p;
}

} // namespace

int main(int argc, char** argv) {
  test::SphereCase c;
  c.order = argc > 1 ? std::atoi(argv[1]) : 2;
  c.size_scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  c.chord_tolerance = (argc > 3 ? std::atof(argv[3]) : 0.02) * test::mm;
  c.probe_radius = 12 * test::mm;
  c.probe_size = (argc > 4 ? std::atof(argv[4]) : 1.0) * test::mm;
  const std::string solver = argc > 5 ? argv[5] : "cg";
  c.solver = solver == "cholmod"     ? LinearSolverKind::cholmod
             : solver == "automatic" ? LinearSolverKind::automatic
                                     : LinearSolverKind::cg;
  const auto s = test::solve_sphere_case(c);
  const double v_error = s->mesh.part_volumes[0] / (4.0 / 3.0 * pi * 1e-6) - 1;
  std::printf(
      "order %d, %zu tets, %d unknowns, magnet volume error %+.3f%%\n"
      "mesh %.1f s, dofs+pattern %.1f s, assemble %.1f s, solve %.1f s (%s, %d iterations)\n",
      c.order, s->mesh.n_tets(), s->assembler->n_unknowns(), 100 * v_error, s->mesh_s, s->setup_s,
      s->report.assemble_s, s->report.solve_s, s->report.linear_solver.c_str(),
      s->report.linear_iterations);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("curved tets %zu, peak memory %.0f MB\n", s->dofs->n_curved(),
              usage.ru_maxrss / 1024.0);
  const PointLocator3D locator(s->mesh);
  const RecoveredB3D rec(*s->field);
  for (double r_mm : {6.0, 12.0}) {
    const ProbeSpec p = sphere_probe(r_mm * test::mm, 37);
    std::printf("r = %.0f mm:\n", r_mm);
    report("element field", sample_probe_3d(*s->field, locator, p, test::mm), norm_of);
    report("recovered field", sample_probe_3d(*s->field, locator, p, test::mm, &rec), norm_of);
  }
  return 0;
}
