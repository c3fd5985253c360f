// Old (field quadrature, validation/analytic_force.hpp) against new (face-pair cubature,
// validation/pair_interaction.hpp) charge interaction: time and error against a converged
// reference (the face-pair cubature at 1e-11 with up to 14 points per direction; the old
// method agrees with it to its own error, see the rows). Errors are relative to |F| and |T|;
// "a priori" is the new method's printed accuracy figure. Prints figures; not a test.
//   magfem_bench_pair [--skip-old]
#include <chrono>
#include <cstdio>
#include <cstring>

#include "validation/analytic_force.hpp"
#include "validation/interaction_cases.hpp"
#include "validation/pair_interaction.hpp"

using namespace magfem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void report(const char* what, const ForceTorque& ft, const ForceTorque& ref, double s) {
  const double f_err = (ft.force - ref.force).norm() / ref.force.norm();
  const double t_err = (ft.torque - ref.torque).norm() / ref.torque.norm();
  std::printf("  %-34s %9.3f s   |F| err %.1e   |T| err %.1e (of |F|, |T|)\n", what, s, f_err,
              t_err);
}

} // namespace

int main(int argc, char** argv) {
  const bool skip_old = argc > 1 && std::strcmp(argv[1], "--skip-old") == 0;
  for (const InteractionCase& c :
       {cylinder_pair_case(), prototype_case(), segment_coupling_case()}) {
    PairInteractionOptions ro;
    ro.tolerance = 1e-11;
    ro.max_order = 14;
    const ForceTorque ref = pair_interaction(c.on, c.by, Eigen::Vector3d::Zero(), ro).on_A;
    std::printf("%s: F = (%.6g, %.6g, %.6g) N, T = (%.6g, %.6g, %.6g) N m\n", c.name, ref.force.x(),
                ref.force.y(), ref.force.z(), ref.torque.x(), ref.torque.y(), ref.torque.z());
    double t_old = 0;
    if (!skip_old) {
      const auto t0 = std::chrono::steady_clock::now();
      ChargeInteractionOptions o;
      const ForceTorque old = charge_interaction(c.on, c.by, Eigen::Vector3d::Zero(), o);
      t_old = seconds_since(t0);
      report("old: field quadrature, tol 1e-6", old, ref, t_old);
    }
    for (double tol : {1e-6, 1e-7}) {
      const auto t0 = std::chrono::steady_clock::now();
      PairInteractionOptions o;
      o.tolerance = tol;
      const PairInteraction p = pair_interaction(c.on, c.by, Eigen::Vector3d::Zero(), o);
      const double s = seconds_since(t0);
      char what[64];
      std::snprintf(what, sizeof what, "new: face pairs, tol %.0e", tol);
      report(what, p.on_A, ref, s);
      std::printf("  %-34s a priori |F| %.1e |T| %.1e, %ld box pairs%s", "",
                  p.force_error / ref.force.norm(), p.torque_error / ref.torque.norm(), p.box_pairs,
                  t_old > 0 ? "" : "\n");
      if (t_old > 0)
        std::printf(", speed-up %.0fx\n", t_old / s);
    }
  }
  return 0;
}
