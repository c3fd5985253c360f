#include "analytic/harmonic_radial.hpp"

#include <cmath>
#include <stdexcept>

namespace magfem {

ShellRadialSolution::ShellRadialSolution(double r_inner, double r_outer,
                                         std::optional<double> permeable_radius)
    : r_inner_(r_inner), r_outer_(r_outer), r_s_(permeable_radius) {
  if (!(r_inner >= 0 && r_outer > r_inner)) {
    throw std::invalid_argument("ShellRadialSolution: need 0 <= r_inner < r_outer");
  }
  if (r_s_ && !(*r_s_ > r_outer)) {
    throw std::invalid_argument("ShellRadialSolution: the permeable sphere must lie outside "
                                "the magnets (R_s > r_outer)");
  }
}

void ShellRadialSolution::evaluate(double rho, int n_max, std::vector<RadialFactors>& out) const {
  out.assign(static_cast<std::size_t>(n_max) + 1, RadialFactors{});
  if (rho >= r_outer_) {
    add_exterior(rho, n_max, out);
  } else if (rho <= r_inner_) {
    add_interior(rho, n_max, out);
  } else {
    add_in_magnet(rho, n_max, out);
  }
  if (r_s_) {
    add_image(rho, n_max, out);
  }
}

// rho >= R_o: g = rho'^n / rho^(n+1); W = R_o (R_o/rho)^(n+1) - R_i (R_i/rho)^(n+1),
// V = W / (n+2), so psi = n W [Mr + (n+1) Mp] / ((n+2)(2n+1)).
void ShellRadialSolution::add_exterior(double rho, int n_max,
                                       std::vector<RadialFactors>& out) const {
  const double qo = r_outer_ / rho, qi = r_inner_ / rho;
  double to = qo, ti = qi; // (R/rho)^(n+1)
  for (int n = 0; n <= n_max; ++n, to *= qo, ti *= qi) {
    const double w = r_outer_ * to - r_inner_ * ti;
    const double alpha = n * w / ((n + 2.0) * (2.0 * n + 1.0));
    const double beta = (n + 1.0) * alpha;
    RadialFactors& f = out[static_cast<std::size_t>(n)];
    f.alpha += alpha;
    f.beta += beta;
    f.d_alpha += -(n + 1.0) * alpha / rho;
    f.d_beta += -(n + 1.0) * beta / rho;
  }
}

// rho <= R_i: g = rho^n / rho'^(n+1); W = R_o (rho/R_o)^n - R_i (rho/R_i)^n,
// V = W / (1 - n) (n != 1) or rho ln(R_o/R_i) (n = 1). Every term goes as rho^n.
void ShellRadialSolution::add_interior(double rho, int n_max,
                                       std::vector<RadialFactors>& out) const {
  const double qo = rho / r_outer_, qi = rho / r_inner_;
  double so = 1.0, si = 1.0; // (rho/R)^n
  for (int n = 0; n <= n_max; ++n, so *= qo, si *= qi) {
    const double w = r_outer_ * so - r_inner_ * si;
    const double v = n == 1 ? rho * std::log(r_outer_ / r_inner_) : w / (1.0 - n);
    const double k = 2.0 * n + 1.0;
    const double alpha = (w - 2.0 * v) / k;
    const double beta = n * (n + 1.0) * v / k;
    RadialFactors& f = out[static_cast<std::size_t>(n)];
    f.alpha += alpha;
    f.beta += beta;
    f.d_alpha += n * alpha / rho;
    f.d_beta += n * beta / rho;
  }
}

// R_i < rho < R_o: the charges split into those below rho (seen as exterior sources) and
// those above (interior sources).
void ShellRadialSolution::add_in_magnet(double rho, int n_max,
                                        std::vector<RadialFactors>& out) const {
  const double qo = rho / r_outer_, qi = r_inner_ / rho;
  const double log_o = std::log(r_outer_ / rho);
  double so = 1.0, ti = qi; // (rho/R_o)^n, (R_i/rho)^(n+1)
  for (int n = 0; n <= n_max; ++n, so *= qo, ti *= qi) {
    const double w = r_outer_ * so - r_inner_ * ti;
    const double dw = (n * r_outer_ * so + (n + 1.0) * r_inner_ * ti) / rho;
    double v = (rho - r_inner_ * ti) / (n + 2.0);
    double dv = (1.0 + (n + 1.0) * r_inner_ * ti / rho) / (n + 2.0);
    if (n == 1) {
      v += rho * log_o;
      dv += log_o - 1.0;
    } else {
      v += (r_outer_ * so - rho) / (1.0 - n);
      dv += (n * r_outer_ * so / rho - 1.0) / (1.0 - n);
    }
    const double k = 2.0 * n + 1.0;
    RadialFactors& f = out[static_cast<std::size_t>(n)];
    f.alpha += (w - 2.0 * v) / k;
    f.d_alpha += (dw - 2.0 * dv) / k;
    f.beta += n * (n + 1.0) * v / k;
    f.d_beta += n * (n + 1.0) * dv / k;
  }
}

// psi = 0 at R_s: subtract the regular solution that matches the exterior solution there.
void ShellRadialSolution::add_image(double rho, int n_max, std::vector<RadialFactors>& out) const {
  const double rs = *r_s_;
  std::vector<RadialFactors> at_rs(static_cast<std::size_t>(n_max) + 1);
  add_exterior(rs, n_max, at_rs);
  const double q = rho / rs;
  double t = 1.0; // (rho/R_s)^n
  for (int n = 0; n <= n_max; ++n, t *= q) {
    const RadialFactors& s = at_rs[static_cast<std::size_t>(n)];
    RadialFactors& f = out[static_cast<std::size_t>(n)];
    f.alpha -= s.alpha * t;
    f.beta -= s.beta * t;
    f.d_alpha -= n * s.alpha * t / rho;
    f.d_beta -= n * s.beta * t / rho;
  }
}

} // namespace magfem
