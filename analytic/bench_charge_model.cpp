// Timing and convergence of the charge model on the thesis's 32-magnet benchmark
// (paper_targets.md A): r56 observation grid (theta, phi 0..90 deg in 2 deg steps, 2116
// points), parallel (centred) and radial, unbounded and bounded by a permeable sphere.
//
// usage: magfem_bench_charge [tolerance=1e-4] [reference_tolerance=1e-8] [threads=0]
//                            [surface_gauss_order] [volume_gauss_order]
// Prints, per case, the time per point (wall, whole model construction included), the error
// against the reference tolerance (max over points of |B - B_ref| / max |B_ref|), and the
// peak |B_rho|.
//
// usage: magfem_bench_charge compensator [tolerance=1e-4] [step_deg=10]
// Prints the Table 4.2 gravity-compensator curve (paper_targets.md B) by charge interaction:
// axial force and torque about y on the inner magnet versus the rotation of the outer one.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "analytic/analytic_force.hpp"
#include "analytic/benchmark32.hpp"
#include "analytic/charge_model.hpp"

namespace {

using magfem::Vec3;

std::vector<Vec3> r56_grid(double radius) {
  std::vector<Vec3> xs;
  for (int i = 0; i <= 45; ++i)
    for (int j = 0; j <= 45; ++j) {
      const double t = i * 2 * magfem::deg_to_rad, p = j * 2 * magfem::deg_to_rad;
      xs.push_back(radius *
                   Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)));
    }
  return xs;
}

struct Run {
  std::vector<Vec3> b;
  double seconds;     // wall
  double cpu_seconds; // all threads (the machine may be shared)
};

int g_surface_order = 0, g_volume_order = 0; // 0 = library default

Run run(magfem::Benchmark32Magnetization kind, bool bounded, double tol, int threads,
        const std::vector<Vec3>& xs) {
  magfem::ChargeModelOptions opt;
  if (g_surface_order > 0)
    opt.gauss_order = g_surface_order;
  if (g_volume_order > 0)
    opt.volume_gauss_order = g_volume_order;
  opt.tolerance = tol;
  opt.n_threads = threads;
  std::vector<magfem::PermeableSphere> spheres;
  if (bounded)
    spheres.push_back({Vec3::Zero(), magfem::Benchmark32::r_observation, true});
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const magfem::ChargeModel model(magfem::make_benchmark32(kind), spheres, opt);
  Run r{model.B(xs), 0, 0};
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu_seconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return r;
}

// Inner solid hemisphere R 29 mm along +z, outer shell 30..43 mm radial inwards (opposed at
// 0 deg), B_r 1.3 T; the outer magnet rotated about y.
int compensator_curve(double tol, double step_deg) {
  magfem::AnalyticMagnet inner;
  inner.shape = magfem::SphericalSegment{0, 0.029, 0, magfem::pi / 2, 0, 2 * magfem::pi};
  inner.magnetization.pattern = magfem::Magnetization::Pattern::parallel;
  inner.magnetization.direction = Vec3::UnitZ();
  inner.B_r = 1.3;
  std::printf("%8s %12s %12s %12s %10s\n", "deg", "F_z N", "F_x N", "T_y Nm", "seconds");
  for (double deg = 0; deg <= 180 + 1e-9; deg += step_deg) {
    magfem::AnalyticMagnet outer;
    outer.shape = magfem::SphericalSegment{0.030, 0.043, 0, magfem::pi / 2, 0, 2 * magfem::pi};
    outer.magnetization.pattern = magfem::Magnetization::Pattern::radial;
    outer.magnetization.sign = -1;
    outer.B_r = 1.3;
    outer.placement =
        magfem::Placement{}.rotated(Vec3::UnitY(), deg * magfem::deg_to_rad, Vec3::Zero());
    magfem::ChargeInteractionOptions opt;
    opt.tolerance = tol;
    opt.field.tolerance = tol;
    const auto t0 = std::chrono::steady_clock::now();
    const magfem::ForceTorque ft = magfem::charge_interaction({inner}, {outer}, Vec3::Zero(), opt);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%8.1f %12.3f %12.3f %12.4f %10.2f\n", deg, ft.force.z(), ft.force.x(),
                ft.torque.y(), s);
  }
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "compensator")
    return compensator_curve(argc > 2 ? std::atof(argv[2]) : 1e-4,
                             argc > 3 ? std::atof(argv[3]) : 10);
  const double tol = argc > 1 ? std::atof(argv[1]) : 1e-4;
  const double ref_tol = argc > 2 ? std::atof(argv[2]) : 1e-8;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 0;
  g_surface_order = argc > 4 ? std::atoi(argv[4]) : 0;
  g_volume_order = argc > 5 ? std::atoi(argv[5]) : 0;
  std::printf("%-18s %-9s %10s %10s %12s %14s %12s\n", "magnetization", "boundary", "ms/point",
              "cpu ms/pt", "ref ms/point", "max err/peak", "peak B_rho T");
  for (auto kind : {magfem::Benchmark32Magnetization::parallel_centred,
                    magfem::Benchmark32Magnetization::radial}) {
    for (bool bounded : {false, true}) {
      // Bounded: the boundary sphere is at 56 mm, so observe just inside it.
      const std::vector<Vec3> xs = r56_grid(bounded ? 0.05599 : 0.056);
      const Run fast = run(kind, bounded, tol, threads, xs);
      const Run ref = run(kind, bounded, ref_tol, threads, xs);
      double peak = 0, peak_rho = 0, err = 0;
      for (std::size_t i = 0; i < xs.size(); ++i) {
        peak = std::max(peak, ref.b[i].norm());
        peak_rho = std::max(peak_rho, std::abs(ref.b[i].dot(xs[i].normalized())));
        err = std::max(err, (fast.b[i] - ref.b[i]).norm());
      }
      std::printf("%-18s %-9s %10.4f %10.4f %12.4f %14.3e %12.6f\n",
                  magfem::to_string(kind).c_str(), bounded ? "R_s=56mm" : "none",
                  1e3 * fast.seconds / xs.size(), 1e3 * fast.cpu_seconds / xs.size(),
                  1e3 * ref.seconds / xs.size(), err / peak, peak_rho);
    }
  }
  return 0;
}
