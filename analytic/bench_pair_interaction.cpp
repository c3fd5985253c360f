// Old (field quadrature, analytic/analytic_force.hpp) against new (face-pair cubature,
// analytic/pair_interaction.hpp) charge interaction: time and error against a converged
// reference (the face-pair cubature at 1e-11 with up to 14 points per direction, its
// bounding-sphere orders only and no mirror symmetry: independent of surface_patch_order.hpp
// and mirror_symmetry.hpp; the old method agrees with it to its own error, see the rows).
// Errors are relative to |F| and |T|; "printed" is the new methods' accuracy figure
// (relative). Times include that estimate (a second run at 100 x the tolerance). The face
// pairs are timed with and without the mirror symmetry, which only some arrangements have.
// Prints figures; not a test.
//   magfem_bench_pair [--skip-old]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "analytic/analytic_force.hpp"
#include "analytic/exterior_field_interaction.hpp"
#include "analytic/interaction_cases.hpp"
#include "analytic/pair_interaction.hpp"

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

// One row of a new method: its result, its printed accuracy, what it counted, the speed-up.
void report_new(const char* method, double tol, const ForceTorque& ft, double force_error,
                double torque_error, const std::string& counted, const ForceTorque& ref, double s,
                double t_old) {
  char what[64];
  std::snprintf(what, sizeof what, "new: %s, tol %.0e", method, tol);
  report(what, ft, ref, s);
  std::printf("  %-34s printed |F| %.1e |T| %.1e, %s", "", force_error / ref.force.norm(),
              torque_error / ref.torque.norm(), counted.c_str());
  if (t_old > 0)
    std::printf(", speed-up %.0fx", t_old / s);
  std::printf("\n");
}

} // namespace

int main(int argc, char** argv) {
  const bool skip_old = argc > 1 && std::strcmp(argv[1], "--skip-old") == 0;
  for (const InteractionCase& c :
       {cylinder_pair_case(), prototype_case(), segment_coupling_case()}) {
    PairInteractionOptions ro;
    ro.tolerance = 1e-11;
    ro.max_order = 14;
    ro.patch_orders = false;    // the bounding-sphere rule alone: independent of the new orders
    ro.mirror_symmetry = false; // ... and of the mirror symmetry
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
    for (double tol : {1e-5, 1e-6}) {
      // The exterior harmonic field, where one group is concentric axisymmetric bodies.
      try {
        const auto t0 = std::chrono::steady_clock::now();
        ExteriorFieldOptions o;
        o.tolerance = tol;
        const ExteriorFieldInteraction e =
            exterior_field_interaction(c.on, c.by, Eigen::Vector3d::Zero(), o);
        report_new("exterior field", tol, e.on, e.force_error, e.torque_error,
                   "degrees <= " + std::to_string(e.n_max), ref, seconds_since(t0), t_old);
      } catch (const std::invalid_argument&) {
        // not that kind of arrangement
      }
    }
    for (double tol : {1e-6, 1e-7}) {
      bool mirrored = false;
      for (bool mirror : {true, false}) {
        const auto t0 = std::chrono::steady_clock::now();
        PairInteractionOptions o;
        o.tolerance = tol;
        o.mirror_symmetry = mirror;
        const PairInteraction p = pair_interaction(c.on, c.by, Eigen::Vector3d::Zero(), o);
        const double s = seconds_since(t0);
        mirrored = mirrored || p.mirrored;
        if (!mirror && !mirrored)
          continue; // no symmetry found: the row above is this one
        report_new(mirror ? "face pairs" : "face pairs w/o mirror", tol, p.on_A, p.force_error,
                   p.torque_error,
                   std::to_string(p.box_pairs) + " box pairs" + (p.mirrored ? ", mirrored" : ""),
                   ref, s, t_old);
      }
    }
  }
  return 0;
}
