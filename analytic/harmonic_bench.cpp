// Timing and agreement of the spherical harmonic model on the thesis's 32-magnet benchmark
// (paper_targets.md A): the full r56 patch (rho 56 mm, theta and phi 0..90 deg in 2-deg steps,
// 2116 points). Prints figures; not a test (the tests use a 6-deg patch).
//   magfem_bench_harmonic [n_max ...]     time per harmonic order (default 150 400 800)
//   magfem_bench_harmonic --compare N     also compare with the charge model at n_max N
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "analytic/benchmark32.hpp"
#include "analytic/charge_model.hpp"
#include "analytic/harmonic_model.hpp"

namespace {

using magfem::Benchmark32Magnetization;
using Vec3 = Eigen::Vector3d;

std::vector<Vec3> r56_patch() {
  std::vector<Vec3> x;
  for (int i = 0; i <= 45; ++i) {
    for (int j = 0; j <= 45; ++j) {
      const double t = 2.0 * i * magfem::deg_to_rad, f = 2.0 * j * magfem::deg_to_rad;
      x.push_back(magfem::Benchmark32::r_observation *
                  Vec3(std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t)));
    }
  }
  return x;
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

magfem::HarmonicOptions options(int n_max, std::optional<double> r_s) {
  magfem::HarmonicOptions o;
  o.n_max = n_max;
  o.permeable_radius = r_s;
  return o;
}

void time_orders(const std::vector<int>& n_list) {
  const auto magnets = magfem::make_benchmark32(Benchmark32Magnetization::parallel_centred);
  const auto x = r56_patch();
  for (int n_max : n_list) {
    const auto t0 = std::chrono::steady_clock::now();
    const magfem::HarmonicModel model(magnets, options(n_max, {}));
    const auto b = model.B(x);
    const double total = since(t0);
    std::printf("n_max %4d: expansion %.3f s, %zu points %.3f s, total %.3f s = %.2f ms per order "
                "(thesis 71 ms)\n",
                n_max, model.setup_seconds(), x.size(), total - model.setup_seconds(), total,
                1e3 * total / n_max);
  }
}

// rms over the patch of the pointwise difference, and eq. 3.117, per spherical component.
void report(const char* what, const std::vector<Vec3>& x, const std::vector<Vec3>& b,
            const std::vector<Vec3>& ref, int n_components) {
  const char* names[] = {"B_rho", "B_theta", "B_phi"};
  for (int c = 0; c < n_components; ++c) {
    double d2 = 0, r2 = 0, b2 = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3 er = x[i].normalized();
      const double st = std::hypot(er.x(), er.y());
      const Vec3 ep = st > 0 ? Vec3(-er.y() / st, er.x() / st, 0) : Vec3(0, 1, 0);
      const Vec3 et = ep.cross(er);
      const Vec3 e = c == 0 ? er : (c == 1 ? et : ep);
      const double bv = b[i].dot(e), rv = ref[i].dot(e);
      d2 += (bv - rv) * (bv - rv);
      r2 += rv * rv;
      b2 += bv * bv;
    }
    std::printf("  %-28s %-8s pointwise rms %.2e %%   eq. 3.117 %+.2e %%\n", what, names[c],
                100 * std::sqrt(d2 / r2), 100 * (std::sqrt(r2) - std::sqrt(b2)) / std::sqrt(r2));
  }
}

double peak_b_rho(const std::vector<Vec3>& x, const std::vector<Vec3>& b) {
  double peak = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    peak = std::max(peak, std::abs(b[i].dot(x[i].normalized())));
  }
  return peak;
}

void compare(int n_max) {
  const auto x = r56_patch();
  magfem::ChargeModelOptions copt;
  copt.tolerance = 1e-8;
  const double r_s = magfem::Benchmark32::r_observation;
  double peak_parallel = 0, peak_radial = 0;
  for (auto kind : {Benchmark32Magnetization::parallel_centred, Benchmark32Magnetization::radial}) {
    const auto magnets = magfem::make_benchmark32(kind);
    for (bool bounded : {false, true}) {
      std::vector<magfem::PermeableSphere> spheres;
      if (bounded) {
        spheres.push_back({Vec3::Zero(), r_s, true});
      }
      auto t0 = std::chrono::steady_clock::now();
      const auto ref = magfem::ChargeModel(magnets, spheres, copt).B(x);
      const double t_charge = since(t0);
      t0 = std::chrono::steady_clock::now();
      const auto b = magfem::HarmonicModel(magnets, spheres, options(n_max, {})).B(x);
      const double t_harm = since(t0);
      const std::string what = magfem::to_string(kind) + (bounded ? " bounded" : " unbounded");
      std::printf("%s: charge model (tol 1e-8) %.2f s, harmonic model (n_max %d) %.2f s\n",
                  what.c_str(), t_charge, n_max, t_harm);
      report(what.c_str(), x, b, ref, bounded ? 1 : 3);
      if (!bounded) {
        (kind == Benchmark32Magnetization::radial ? peak_radial : peak_parallel) = peak_b_rho(x, b);
      }
    }
  }
  std::printf("peak |B_rho| on r56 (harmonic): parallel %.4f T, radial %.4f T: radial %.1f %% "
              "lower (thesis: about 20 %%)\n",
              peak_parallel, peak_radial, 100 * (1 - peak_radial / peak_parallel));
}

} // namespace

int main(int argc, char** argv) {
  std::vector<int> n_list;
  int compare_n = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--compare" && i + 1 < argc) {
      compare_n = std::atoi(argv[++i]);
    } else {
      n_list.push_back(std::atoi(a.c_str()));
    }
  }
  if (n_list.empty() && compare_n == 0) {
    n_list = {150, 400, 800};
  }
  time_orders(n_list);
  if (compare_n > 0) {
    compare(compare_n);
  }
  return 0;
}
