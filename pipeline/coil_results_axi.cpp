#include "pipeline/coil_results_axi.hpp"

#include <algorithm>
#include <stdexcept>

#include "casefile/symmetry_check2d.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/symmetry2d.hpp"
#include "postproc/coil_linkage_axi.hpp"
#include "solver/assembler2d.hpp"
#include "solver/current_sensitivity2d.hpp"

namespace magfem {
namespace {

// The sensitivity solves of the differential inductance stop at 1e-9 relative residual when
// they are iterative (as in 3D, coil_run3d.cpp); direct solves are exact whatever it is.
LinearSolverOptions sensitivity_options(LinearSolverOptions options) {
  options.cg_tolerance = std::max(options.cg_tolerance, 1e-9);
  // Part of post-processing: its factorization is no stage of its own on the console (it
  // reported "factorization" after "post-processing").
  options.progress = nullptr;
  return options;
}

// A coil of the whole device and the meshed coil that stands for it.
struct WholeCoil {
  int region = 0;     // spec.regions index
  int meshed = 0;     // index into the meshed coils (itself when meshed)
  bool image = false; // beyond the plane: the mirror image of coil `meshed`
  bool pair = false;  // one of a mirrored pair (image or meshed)
};

// The whole device's coils in spec order, and the meshed ones with their loads per ampere.
struct CoilLayout {
  std::vector<WholeCoil> whole;
  std::vector<CurrentPerAmpere2D> meshed;
};

CoilLayout coil_layout(const Run2D& run, const std::vector<int>& mirror) {
  const CaseSpec& spec = run.spec;
  std::vector<bool> has_elements(spec.regions.size(), false);
  for (const int p : run.mesh.triangle_part)
    if (p >= 0)
      has_elements[std::size_t(p)] = true;
  const auto areas = whole_part_areas(spec, run.mesh);
  CoilLayout out;
  for (std::size_t i = 0; i < spec.regions.size(); ++i) {
    const RegionSpec& r = spec.regions[i];
    if (r.turns == 0 || !has_elements[i])
      continue;
    const bool pair = !mirror.empty() && mirror[i] != int(i);
    out.whole.push_back({int(i), int(out.meshed.size()), false, pair});
    out.meshed.push_back({int(i), r.turns / areas[i]});
  }
  for (std::size_t i = 0; i < spec.regions.size(); ++i) {
    if (spec.regions[i].turns == 0 || has_elements[i])
      continue;
    // An image beyond the plane (check_symmetry_2d: its image is a meshed coil with turns).
    const auto m = std::find_if(out.meshed.begin(), out.meshed.end(), [&](const auto& c) {
      return !mirror.empty() && c.part == mirror[i];
    });
    if (m == out.meshed.end()) // covered by later parts: as flux_linkage_axi says
      throw std::invalid_argument("coil '" + spec.regions[i].name + "' has no element");
    out.whole.push_back({int(i), int(m - out.meshed.begin()), true, true});
  }
  std::stable_sort(out.whole.begin(), out.whole.end(),
                   [](const WholeCoil& a, const WholeCoil& b) { return a.region < b.region; });
  return out;
}

} // namespace

void compute_coil_results_axi(Run2D& run, const Assembler2D& assembler, const Eigen::VectorXd& u) {
  run.coil_results.clear();
  run.inductance_H.resize(0, 0);
  const CaseSpec& spec = run.spec;
  if (!spec.axisymmetric())
    return;
  // Axisymmetric cases have one plane at most (z = 0).
  const auto& planes = spec.geometry2d.planes;
  const double s = !planes.empty() && planes[0].field == SymmetryField::parallel ? -1 : 1;
  const std::vector<int> mirror = planes.empty() ? std::vector<int>{} : mirror_parts_2d(spec)[0];
  const auto [whole, meshed] = coil_layout(run, mirror);

  const LinearSolverOptions options = sensitivity_options(spec.newton.linear);
  // Per meshed coil, all-DOF sensitivities under the plane's own condition (symmetric: the
  // coil and its image driven as the condition says) and, for pairs, the other condition
  // (antisymmetric: the image driven the other way).
  std::vector<Eigen::VectorXd> sym, anti;
  for (Eigen::VectorXd& du :
       current_sensitivities_2d(run.problem, *run.dofs, assembler, u, meshed, options))
    sym.push_back(assembler.expand(du));
  std::vector<CurrentPerAmpere2D> pairs;
  std::vector<int> pair_of_meshed(meshed.size(), -1);
  for (const WholeCoil& c : whole)
    if (c.pair && !c.image) {
      pair_of_meshed[std::size_t(c.meshed)] = int(pairs.size());
      pairs.push_back(meshed[std::size_t(c.meshed)]);
    }
  if (!pairs.empty()) {
    const auto du = complementary_sensitivities_2d(run.problem, *run.dofs, assembler.expand(u), 0,
                                                   pairs, options);
    anti.resize(meshed.size());
    for (std::size_t m = 0; m < meshed.size(); ++m)
      if (pair_of_meshed[m] >= 0)
        anti[m] = du[std::size_t(pair_of_meshed[m])];
  }

  auto turns = [&](int region) { return spec.regions[std::size_t(region)].turns; };
  auto meshed_region = [&](const WholeCoil& c) { return meshed[std::size_t(c.meshed)].part; };
  // Whole-device linkage of coil J with a field of the share (a_sign: the potential at a
  // point beyond the plane over that at its image): the meshed coil's, or its image's.
  auto linkage = [&](const WholeCoil& j, const Field2D& field, double a_sign) {
    const int m = meshed_region(j);
    const double lambda = flux_linkage_axi(field, m, turns(m));
    return j.image ? a_sign * turns(j.region) / turns(m) * lambda : lambda;
  };
  auto field_of = [&](const Eigen::VectorXd& a) { return Field2D(run.problem, *run.dofs, a); };

  const auto n = Eigen::Index(whole.size());
  run.inductance_H = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const WholeCoil& kc = whole[std::size_t(k)];
    const std::size_t m = std::size_t(kc.meshed);
    const Field2D f_sym = field_of(sym[m]);
    if (!kc.pair) {
      for (Eigen::Index j = 0; j < n; ++j)
        run.inductance_H(j, k) = linkage(whole[std::size_t(j)], f_sym, s);
      continue;
    }
    // The unit current in K as the two excitations of its meshed coil M: e_M = (S + A) / 2,
    // e_image = (S - A) / (2 t), t = s N_M / N_image the image's current in S per ampere in M.
    const Field2D f_anti = field_of(anti[m]);
    const double t = kc.image ? s * turns(meshed_region(kc)) / turns(kc.region) : 1;
    const double w_anti = kc.image ? -1 : 1;
    for (Eigen::Index j = 0; j < n; ++j) {
      const WholeCoil& jc = whole[std::size_t(j)];
      // A coil on the plane links nothing of the antisymmetric field (its potential is odd).
      const double l_anti = jc.pair ? linkage(jc, f_anti, -s) : 0.0;
      run.inductance_H(j, k) = (linkage(jc, f_sym, s) + w_anti * l_anti) / (2 * t);
    }
  }

  for (Eigen::Index j = 0; j < n; ++j) {
    const WholeCoil& c = whole[std::size_t(j)];
    const RegionSpec& r = spec.regions[std::size_t(c.region)];
    CoilResult2D out;
    out.name = r.name;
    out.turns = r.turns;
    out.current_A = r.current;
    out.flux_linkage_Wb = linkage(c, *run.field, s);
    out.linkage_per_ampere_H = r.current != 0 ? out.flux_linkage_Wb / r.current : 0.0;
    out.inductance_H = run.inductance_H(j, j);
    if (c.pair)
      out.mirror_image = spec.regions[std::size_t(mirror[std::size_t(c.region)])].name;
    run.coil_results.push_back(out);
  }
}

} // namespace magfem
