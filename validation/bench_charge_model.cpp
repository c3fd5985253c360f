// Timing and convergence of the charge model on the thesis's 32-magnet benchmark
// (paper_targets.md A): r56 observation grid (theta, phi 0..90 deg in 2 deg steps, 2116
// points), parallel (centred) and radial, unbounded and bounded by a permeable sphere.
//
// usage: magfem_bench_charge [tolerance=1e-4] [reference_tolerance=1e-8] [threads=0]
// Prints, per case, the time per point (wall, whole model construction included), the error
// against the reference tolerance (max over points of |B - B_ref| / max |B_ref|), and the
// peak |B_rho|.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "validation/benchmark32.hpp"
#include "validation/charge_model.hpp"

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

Run run(magfem::Benchmark32Magnetization kind, bool bounded, double tol, int threads,
        const std::vector<Vec3>& xs) {
  magfem::ChargeModelOptions opt;
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

} // namespace

int main(int argc, char** argv) {
  const double tol = argc > 1 ? std::atof(argv[1]) : 1e-4;
  const double ref_tol = argc > 2 ? std::atof(argv[2]) : 1e-8;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 0;
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
