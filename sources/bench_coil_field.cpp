// Speed and accuracy of the coil source field on the case it is built for: 12 coils on a
// sphere (the thesis's spherical actuator: r 63..72 mm, alpha 3.7..18.4 deg, axes at the
// vertices of an icosahedron) evaluated at 1 M random points of a 0.2 m box, as the FE solver
// does at its quadrature points. Prints the time (CoilSet::H_at on all cores) and the error
// against a high-order reference (bundle integration only, tolerance 1e-13, near order 12)
// on a subset, binned by the distance of the point from the coil's bundle.
//
//   magfem_bench_coil_field [n_points] [n_reference] [threads]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>
#include <vector>

#include <Eigen/Geometry>

#include "core/constants.hpp"
#include "sources/coil_set.hpp"

namespace {

using magfem::Vec3;

std::vector<magfem::Coil3D> sphere_coils() {
  const double g = 0.5 * (1 + std::sqrt(5.0));
  std::vector<Vec3> axes;
  for (const double s1 : {-1.0, 1.0}) {
    for (const double s2 : {-1.0, 1.0}) {
      axes.emplace_back(0, s1, s2 * g);
      axes.emplace_back(s1, s2 * g, 0);
      axes.emplace_back(s2 * g, 0, s1);
    }
  }
  std::vector<magfem::Coil3D> coils;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    magfem::Coil3D c;
    c.name = "coil" + std::to_string(k);
    c.shape =
        magfem::SphericalCoil{0.063, 0.072, 3.7 * magfem::deg_to_rad, 18.4 * magfem::deg_to_rad};
    c.turns = 200;
    c.current = k % 2 ? 1.0 : -1.0;
    c.placement.rotation =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axes[k].normalized()).toRotationMatrix();
    coils.push_back(c);
  }
  return coils;
}

} // namespace

int main(int argc, char** argv) {
  const std::size_t n_points = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 1000000;
  const std::size_t n_ref = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 20000;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 0;
  const std::vector<magfem::Coil3D> coils = sphere_coils();

  auto t0 = std::chrono::steady_clock::now();
  const magfem::CoilSet set(coils);
  auto t1 = std::chrono::steady_clock::now();
  std::mt19937_64 gen(42);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec3> points(n_points);
  for (Vec3& p : points) {
    p = Vec3(u(gen), u(gen), u(gen));
  }
  std::vector<Vec3> h;
  auto t2 = std::chrono::steady_clock::now();
  set.H_at(points, h, threads);
  auto t3 = std::chrono::steady_clock::now();
  const double setup = std::chrono::duration<double>(t1 - t0).count();
  const double eval = std::chrono::duration<double>(t3 - t2).count();
  const unsigned used = threads > 0 ? static_cast<unsigned>(threads)
                                    : std::max(1u, std::thread::hardware_concurrency());
  std::printf("12 spherical coils, %zu points in a 0.2 m box, %u threads\n", n_points, used);
  std::printf("  setup %.3f s, evaluation %.3f s: %.3f us per (point, coil) on one core\n", setup,
              eval, eval * used / (static_cast<double>(n_points) * coils.size()) * 1e6);

  // Reference: bundle integration only, at tolerance 1e-13 and near order 12.
  magfem::CoilFieldOptions ref_options;
  ref_options.use_expansions = false;
  ref_options.tolerance = 1e-13;
  ref_options.near_order = 12;
  ref_options.far_order_max = 40;
  const magfem::CoilSet ref(coils, ref_options);
  // Error of each coil's field relative to its own size there (and to the larger of that and
  // the bundle's characteristic field N I / size, the measure inside the winding, where the
  // field changes sign), by distance from its bundle: inside, < 1 mm, < 1 cm, beyond.
  const char* names[] = {"inside the bundle", "within 1 mm", "within 1 cm", "beyond 1 cm"};
  double worst[4] = {0, 0, 0, 0}, worst_char[4] = {0, 0, 0, 0}, total_worst = 0;
  long count[4] = {0, 0, 0, 0};
  const std::size_t n_check = std::min(n_ref, n_points);
  for (std::size_t i = 0; i < n_check; ++i) {
    const Vec3& x = points[i];
    Vec3 sum = Vec3::Zero();
    double sum_abs = 0;
    for (int k = 0; k < set.size(); ++k) {
      const Vec3 hr = ref.H_of(k, x), hf = set.H_of(k, x);
      sum += hr;
      sum_abs += hr.norm();
      const magfem::CoilField& f = set.field(k);
      const Vec3 xl = f.coil().placement.to_local(x);
      const auto& s = std::get<magfem::SphericalCoil>(f.coil().shape);
      const double r = xl.norm(), alpha = std::atan2(std::hypot(xl.x(), xl.y()), xl.z());
      // Distance to the bundle, roughly: radial and arc-length excesses.
      const double dr = std::max({s.r_inner - r, 0.0, r - s.r_outer});
      const double da = r * std::max({s.alpha_min - alpha, 0.0, alpha - s.alpha_max});
      const double d = std::hypot(dr, da);
      const int bin = f.contains(x) ? 0 : d < 1e-3 ? 1 : d < 1e-2 ? 2 : 3;
      const double size = std::max(s.r_outer - s.r_inner, s.r_outer * (s.alpha_max - s.alpha_min));
      const double h_char = f.coil().turns * std::abs(f.coil().current) / size;
      const double err = (hf - hr).norm();
      worst[bin] = std::max(worst[bin], err / hr.norm());
      worst_char[bin] = std::max(worst_char[bin], err / std::max(hr.norm(), h_char));
      ++count[bin];
    }
    // The coils' fields partly cancel: relative to the sum of their sizes.
    total_worst = std::max(total_worst, (h[i] - sum).norm() / sum_abs);
  }
  std::printf("max error of each coil's field against the reference (%zu points):\n", n_check);
  std::printf("  %-18s %9s  %12s  %22s\n", "", "pairs", "/ |H|", "/ max(|H|, N I / size)");
  for (int b = 0; b < 4; ++b) {
    std::printf("  %-18s %9ld  %12.2e  %22.2e\n", names[b], count[b], worst[b], worst_char[b]);
  }
  std::printf("  total field of the 12 coils, / sum of their |H|: %.2e\n", total_worst);
  return 0;
}
