#include "sources/arc_bundle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/constants.hpp"

namespace magfem {

namespace {

double interval_distance(double x, double lo, double hi) {
  return std::max({lo - x, 0.0, x - hi});
}

// An arc-angle rule with what the kernel needs at each node.
struct ArcRule {
  std::vector<double> w, cos_psi, sin2_half; // weight, cos(psi), sin^2(psi / 2)
  void clear() {
    w.clear();
    cos_psi.clear();
    sin2_half.clear();
  }
  void add(double psi, double weight) {
    const double s = std::sin(0.5 * psi);
    w.push_back(weight);
    cos_psi.push_back(std::cos(psi));
    sin2_half.push_back(s * s);
  }
  // A node given by cos(psi); only for plain rules, whose nodes stay away from psi = 0 relative
  // to the filament's distance, so that (1 - cos psi) / 2 loses nothing that matters.
  void add_cos(double c, double weight) {
    w.push_back(weight);
    cos_psi.push_back(c);
    sin2_half.push_back(0.5 * (1.0 - c));
  }
};

} // namespace

// The field point in the ring's cylindrical coordinates. psi = phi' - phi runs over the arc as
// seen from the point, shifted by a multiple of 2 pi so that the arc's middle lies in
// [-pi, pi]; the filament integrand is singular near psi = `psi_sing`, the multiple of 2 pi
// closest to the arc. The plain Gauss rules over the arc are the same for every filament and
// are built once per point and order.
struct ArcBundle::PointFrame {
  double rho, z;
  double cos_phi, sin_phi; // the point's angle
  double psi0, psi1, psi_sing;
  double cos0, cos1, s0, s1; // cos(psi) and sin^2(psi / 2) at the arc's ends
  int n_entire;              // order the entire factor cos(psi) needs
  std::array<ArcRule, max_cached_gauss_order + 1>* plain;
  std::array<bool, max_cached_gauss_order + 1>* built;
};

ArcBundle::ArcBundle(const Vec3& center, double phi0, double phi1, double a0, double a1, double z0,
                     double z1, double current, const CoilFieldOptions& options)
    : center_(center), phi0_(phi0), phi1_(phi1), a0_(a0), a1_(a1), z0_(z0), z1_(z1),
      options_(options) {
  check_options(options);
  if (!(phi1 > phi0 && phi1 - phi0 <= 2 * pi && a0 >= 0 && a1 > a0 && z1 > z0)) {
    throw std::invalid_argument(
        "ArcBundle: need phi0 < phi1 <= phi0 + 2 pi, 0 <= a0 < a1, z0 < z1");
  }
  current_density_ = current / ((a1 - a0) * (z1 - z0));
  // Graded arc panels [0.2 l, l] see the singularity at least 0.2 l from their inner end: the
  // order for the tolerance there (11 at 1e-8). The arc rule is cheap next to the cross-section
  // rule, so it is kept at the tolerance even for the near points' filaments.
  graded_order_ =
      std::max(options.near_order, gauss_order_for(0.6, 0.4, 0.0, 0.0, options.tolerance, 2,
                                                   max_cached_gauss_order - 1));
  n_entire_ =
      gauss_order_entire(1.0, 0.5 * (phi1 - phi0), options.tolerance, 2, options.far_order_max);
  for (int n = 1; n <= options.far_order_max; ++n) {
    const QuadratureRule& g = cached_gauss(n);
    ArcNodes nodes;
    for (std::size_t k = 0; k < g.x.size(); ++k) {
      const double phi = 0.5 * (phi0 + phi1) + 0.5 * (phi1 - phi0) * g.x[k];
      nodes.w.push_back(0.5 * (phi1 - phi0) * g.w[k]);
      nodes.cos_phi.push_back(std::cos(phi));
      nodes.sin_phi.push_back(std::sin(phi));
    }
    arc_nodes_.push_back(std::move(nodes));
  }
}

// H_rho = dI a dz / (4 pi) int cos(psi) D^-3, H_z = dI a / (4 pi) int (a - rho cos(psi)) D^-3,
// D^2 = alpha^2 + 4 a rho sin^2(psi / 2) (alpha the meridian distance; written so that D stays
// accurate near the filament), and H_phi = dI a dz (cos psi0 - cos psi1) / (2 pi D0 D1 (D0 + D1))
// exactly (sin(psi) D^-3 is a derivative). D^2 vanishes at psi = +- 2 i asinh(alpha / 2 sqrt(a
// rho)), which sets the plain rule's order; closer filaments get panels graded towards psi = 0.
void ArcBundle::add_arc(double a, double zf, double di, const PointFrame& f, int n_psi,
                        ArcSums& sums) const {
  const double dz = f.z - zf, da = a - f.rho;
  const double alpha2 = da * da + dz * dz, k4 = 4.0 * a * f.rho;
  const double d0 = std::sqrt(alpha2 + k4 * f.s0), d1 = std::sqrt(alpha2 + k4 * f.s1);
  if (d0 > 0 && d1 > 0) {
    sums.h_phi += di * dz * a * (f.cos0 - f.cos1) / (2.0 * pi * d0 * d1 * (d0 + d1));
  }
  const double im =
      k4 > 0 ? 2.0 * std::asinh(std::sqrt(alpha2 / k4)) : std::numeric_limits<double>::infinity();
  const double mid = 0.5 * (f.psi0 + f.psi1), half = 0.5 * (f.psi1 - f.psi0);
  const int n_max = options_.far_order_max;
  const int n = n_psi > 0
                    ? n_psi
                    : std::max(f.n_entire, gauss_order_for(mid, half, f.psi_sing, std::min(im, 1e3),
                                                           options_.tolerance, 2, n_max));
  const ArcRule* rule;
  thread_local ArcRule graded;
  if (n <= n_max) {
    const auto i = static_cast<std::size_t>(n);
    if (!(*f.built)[i]) {
      // cos(phi'_k - phi) from the arc's own nodes phi'_k, tabulated: no trigonometry per point.
      ArcRule& r = (*f.plain)[i];
      r.clear();
      const ArcNodes& nodes = arc_nodes_[i - 1];
      for (std::size_t k = 0; k < nodes.w.size(); ++k) {
        r.add_cos(nodes.cos_phi[k] * f.cos_phi + nodes.sin_phi[k] * f.sin_phi, nodes.w[k]);
      }
      (*f.built)[i] = true;
    }
    rule = &(*f.plain)[i];
  } else {
    thread_local std::vector<Node1> nodes;
    nodes.clear();
    append_graded_rule(f.psi0, f.psi1, f.psi_sing, im, graded_order_, 0.2, 1, false, nodes);
    graded.clear();
    for (const Node1& node : nodes) {
      graded.add(node.x, node.w);
    }
    rule = &graded;
  }
  double i0 = 0, ic = 0;
  for (std::size_t k = 0; k < rule->w.size(); ++k) {
    const double d2 = alpha2 + k4 * rule->sin2_half[k];
    const double inv3 = rule->w[k] / (d2 * std::sqrt(d2));
    i0 += inv3;
    ic += inv3 * rule->cos_psi[k];
  }
  sums.h_rho += di * a * dz / (4.0 * pi) * ic;
  sums.h_z += di * a / (4.0 * pi) * (a * i0 - f.rho * ic);
}

// Cross-section rule as for a loop bundle (the singularity of the arc-integrated kernel sits at
// the field point's meridian position when its angle lies within the arc); beyond the arc's
// ends the chord e to the nearest end moves it off the real axis, as for a straight bundle.
Vec3 ArcBundle::H(const Vec3& x) const {
  const Vec3 r = x - center_;
  const double rho = std::hypot(r.x(), r.y());
  const double phi = std::atan2(r.y(), r.x());
  const double span = phi1_ - phi0_;
  const double delta = std::remainder(0.5 * (phi0_ + phi1_) - phi, 2.0 * pi);
  PointFrame f;
  f.rho = rho;
  f.z = r.z();
  f.cos_phi = rho > 0 ? r.x() / rho : 1.0;
  f.sin_phi = rho > 0 ? r.y() / rho : 0.0;
  f.psi0 = delta - 0.5 * span;
  f.psi1 = delta + 0.5 * span;
  f.psi_sing = 0.0;
  for (const double k : {-2.0 * pi, 2.0 * pi}) {
    if (interval_distance(k, f.psi0, f.psi1) < interval_distance(f.psi_sing, f.psi0, f.psi1)) {
      f.psi_sing = k;
    }
  }
  f.cos0 = std::cos(f.psi0);
  f.cos1 = std::cos(f.psi1);
  f.s0 = std::pow(std::sin(0.5 * f.psi0), 2);
  f.s1 = std::pow(std::sin(0.5 * f.psi1), 2);
  f.n_entire = n_entire_;
  thread_local std::array<ArcRule, max_cached_gauss_order + 1> plain;
  thread_local std::array<bool, max_cached_gauss_order + 1> built;
  built.fill(false);
  f.plain = &plain;
  f.built = &built;

  const double outside = std::max(0.0, std::abs(delta) - 0.5 * span);
  const double e = outside > 0 ? 2.0 * rho * std::sin(0.5 * std::min(outside, pi)) : 0.0;
  const double dist_a = interval_distance(rho, a0_, a1_), dist_z = interval_distance(f.z, z0_, z1_);
  const double tol = options_.tolerance;
  const int n_max = options_.far_order_max;
  const double ma = 0.5 * (a0_ + a1_), ha = 0.5 * (a1_ - a0_);
  const double mz = 0.5 * (z0_ + z1_), hz = 0.5 * (z1_ - z0_);
  const int na = gauss_order_for(ma, ha, rho, std::hypot(dist_z, e), tol, 2, n_max, 2, 0.0);
  const int nz = gauss_order_for(mz, hz, f.z, std::hypot(dist_a, e), tol, 2, n_max);
  ArcSums sums;
  if (na <= n_max && nz <= n_max) {
    // One arc rule for all filaments, from the closest one: alpha >= d_cs and a <= a1 bound
    // the singularity's distance from below.
    const double d_cs = std::hypot(dist_a, dist_z);
    const double im_min = rho > 0 ? 2.0 * std::asinh(d_cs / (2.0 * std::sqrt(a1_ * rho))) : 1e3;
    const int n_psi =
        std::max(f.n_entire, gauss_order_for(0.5 * (f.psi0 + f.psi1), 0.5 * span, f.psi_sing,
                                             std::min(im_min, 1e3), tol, 2, n_max + 1));
    const QuadratureRule& ga = cached_gauss(na);
    const QuadratureRule& gz = cached_gauss(nz);
    for (std::size_t i = 0; i < ga.x.size(); ++i) {
      for (std::size_t j = 0; j < gz.x.size(); ++j) {
        add_arc(ma + ha * ga.x[i], mz + hz * gz.x[j],
                current_density_ * ha * hz * ga.w[i] * gz.w[j], f, n_psi <= n_max ? n_psi : 0,
                sums);
      }
    }
  } else {
    const double d_cs = std::hypot(dist_a, dist_z);
    NearPoint p;
    p.u = rho;
    p.v = f.z;
    p.su = p.sv = 1.0;
    if (outside > 0) {
      p.width = std::hypot(d_cs, e);
    } else {
      const double inside = 0.5 * span - std::abs(delta); // angle to the nearer end
      p.width = d_cs > 0 ? d_cs : 2.0 * rho * std::sin(0.5 * std::min(inside, pi));
    }
    p.singular = d_cs == 0 && outside == 0;
    p.n = options_.near_order;
    thread_local std::vector<Node2> nodes;
    nodes.clear();
    append_near_rule({a0_, a1_, z0_, z1_}, p, nodes);
    for (const Node2& node : nodes) {
      add_arc(node.u, node.v, current_density_ * node.w, f, 0, sums);
    }
  }
  const double c = f.cos_phi, s = f.sin_phi;
  return {sums.h_rho * c - sums.h_phi * s, sums.h_rho * s + sums.h_phi * c, sums.h_z};
}

} // namespace magfem
