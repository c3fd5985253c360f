#include "analytic/harmonic_expansion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <thread>
#include <utility>

#include "core/constants.hpp"

namespace magfem {

std::vector<double> ShellExpansion::degree_amplitude() const {
  std::vector<double> amp(static_cast<std::size_t>(index.n_max()) + 1, 0.0);
  for (int m = 0; m <= index.n_max(); ++m) {
    const double norm = m == 0 ? 1.0 : 0.5;
    for (int n = m; n <= index.n_max(); ++n) {
      const std::size_t k = index(n, m);
      const double nn1 = static_cast<double>(n) * (n + 1);
      amp[static_cast<std::size_t>(n)] +=
          norm * (radial_cos[k] * radial_cos[k] + radial_sin[k] * radial_sin[k] +
                  nn1 * (poloidal_cos[k] * poloidal_cos[k] + poloidal_sin[k] * poloidal_sin[k]));
    }
  }
  for (double& a : amp) {
    a = std::sqrt(a);
  }
  return amp;
}

namespace {

// Closed-form phi integrals over [phi_min, phi_max] of cos(k phi) and sin(k phi), any integer k.
struct PhiIntegrals {
  double lo, hi;
  double cos_k(int k) const { return k == 0 ? hi - lo : (std::sin(k * hi) - std::sin(k * lo)) / k; }
  double sin_k(int k) const { return k == 0 ? 0.0 : (std::cos(k * lo) - std::cos(k * hi)) / k; }
};

// Phi projections (onto cos m phi and sin m phi) of the functions that make up M in a band:
//   M_rho = sin(t) F1 + cos(t) F2 + F3,  M_theta = cos(t) F1 - sin(t) F2,  M_phi = G,
// with F1 = Mx cos phi + My sin phi, F2 = Mz, G = -Mx sin phi + My cos phi (parallel
// segments) and F3 = the radial magnitude.
struct PhiProjection {
  double f1c = 0, f1s = 0, f2c = 0, f2s = 0, f3c = 0, f3s = 0, gc = 0, gs = 0;
};

struct Band {
  double theta_min, theta_max;
  std::vector<PhiProjection> proj; // per m
};

void add_segment(const ShellSegmentSource& s, int n_max, std::vector<PhiProjection>& proj) {
  const PhiIntegrals in{s.phi_min, s.phi_max};
  const double mx = s.parallel.x(), my = s.parallel.y(), mz = s.parallel.z();
  for (int m = 0; m <= n_max; ++m) {
    const double cc = 0.5 * (in.cos_k(m - 1) + in.cos_k(m + 1)); // cos(phi) cos(m phi)
    const double sc = 0.5 * (in.sin_k(m + 1) - in.sin_k(m - 1)); // sin(phi) cos(m phi)
    const double cs = 0.5 * (in.sin_k(m + 1) + in.sin_k(m - 1)); // cos(phi) sin(m phi)
    const double ss = 0.5 * (in.cos_k(m - 1) - in.cos_k(m + 1)); // sin(phi) sin(m phi)
    PhiProjection& p = proj[static_cast<std::size_t>(m)];
    p.f1c += mx * cc + my * sc;
    p.f1s += mx * cs + my * ss;
    p.f2c += mz * in.cos_k(m);
    p.f2s += mz * in.sin_k(m);
    p.f3c += s.radial * in.cos_k(m);
    p.f3s += s.radial * in.sin_k(m);
    p.gc += -mx * sc + my * cc;
    p.gs += -mx * ss + my * cs;
  }
}

std::vector<Band> make_bands(const std::vector<ShellSegmentSource>& segments, int n_max) {
  std::map<std::pair<double, double>, std::size_t> slot;
  std::vector<Band> bands;
  for (const ShellSegmentSource& s : segments) {
    const auto key = std::make_pair(s.theta_min, s.theta_max);
    auto it = slot.find(key);
    if (it == slot.end()) {
      it = slot.emplace(key, bands.size()).first;
      bands.push_back({s.theta_min, s.theta_max,
                       std::vector<PhiProjection>(static_cast<std::size_t>(n_max) + 1)});
    }
    add_segment(s, n_max, bands[it->second].proj);
  }
  return bands;
}

// Quadrature node of one band with its weight times sin(theta) (the area element).
struct NodeFactors {
  double st = 0, ct = 0, ws = 0;
  const Band* band = nullptr;
};

// A polar angle at which the Legendre columns are generated, used by its own band's node and
// possibly by the mirror node pi - theta of a band mirrored about the equator:
// Pbar_nm(pi - t) = (-1)^(n+m) Pbar_nm(t), so one column serves both.
struct EvalNode {
  double theta = 0;
  NodeFactors direct;
  NodeFactors mirror; // band == nullptr: none
};

// The integrand is a trigonometric polynomial of degree n_max + 2 in theta; on a band of
// width h that is a frequency omega = (n_max + 2) h / 2 on the reference interval, whose
// Legendre coefficients vanish to round-off beyond degree omega + O(omega^(1/3)). A q-node
// rule integrates degrees up to 2q - 1 exactly.
QuadratureRule band_rule(const Band& band, int n_max, double scale) {
  const double omega = 0.5 * (n_max + 2) * (band.theta_max - band.theta_min);
  const int q = static_cast<int>(std::ceil(scale * (0.5 * omega + 3.0 * std::cbrt(omega) + 10.0)));
  return gauss_legendre(q, band.theta_min, band.theta_max);
}

NodeFactors factors(const Band& band, const QuadratureRule& rule, std::size_t i) {
  const double st = std::sin(rule.x[i]);
  return {st, std::cos(rule.x[i]), rule.w[i] * st, &band};
}

bool mirrored(const Band& a, const Band& b) {
  constexpr double tol = 1e-14;
  return std::abs(a.theta_min + b.theta_max - pi) < tol &&
         std::abs(a.theta_max + b.theta_min - pi) < tol;
}

std::vector<EvalNode> make_nodes(const std::vector<Band>& bands, int n_max, double scale) {
  std::vector<EvalNode> nodes;
  std::vector<bool> used(bands.size(), false);
  for (std::size_t a = 0; a < bands.size(); ++a) {
    if (used[a]) {
      continue;
    }
    used[a] = true;
    const QuadratureRule ra = band_rule(bands[a], n_max, scale);
    const std::size_t q = ra.x.size();
    std::size_t b = a + 1;
    while (b < bands.size() && (used[b] || !mirrored(bands[a], bands[b]))) {
      ++b;
    }
    if (b < bands.size()) { // a mirror band: its node q-1-i is pi minus node i of a
      used[b] = true;
      const QuadratureRule rb = band_rule(bands[b], n_max, scale);
      for (std::size_t i = 0; i < q; ++i) {
        nodes.push_back({ra.x[i], factors(bands[a], ra, i), factors(bands[b], rb, q - 1 - i)});
      }
    } else if (mirrored(bands[a], bands[a])) { // symmetric about the equator itself
      for (std::size_t i = 0; i < q / 2; ++i) {
        nodes.push_back({ra.x[i], factors(bands[a], ra, i), factors(bands[a], ra, q - 1 - i)});
      }
      if (q % 2 == 1) {
        nodes.push_back({ra.x[q / 2], factors(bands[a], ra, q / 2), {}});
      }
    } else {
      for (std::size_t i = 0; i < q; ++i) {
        nodes.push_back({ra.x[i], factors(bands[a], ra, i), {}});
      }
    }
  }
  return nodes;
}

// Integrand weights of one node for order m: radial (cos, sin), theta part of the poloidal
// projection (cos, sin) and phi part (g_cos, g_sin).
struct OrderWeights {
  double rc = 0, rs = 0, tc = 0, ts = 0, gc = 0, gs = 0;
};

OrderWeights order_weights(const NodeFactors& nf, int m) {
  if (nf.band == nullptr) {
    return {};
  }
  const PhiProjection& pr = nf.band->proj[static_cast<std::size_t>(m)];
  return {nf.ws * (nf.st * pr.f1c + nf.ct * pr.f2c + pr.f3c),
          nf.ws * (nf.st * pr.f1s + nf.ct * pr.f2s + pr.f3s),
          nf.ws * (nf.ct * pr.f1c - nf.st * pr.f2c),
          nf.ws * (nf.ct * pr.f1s - nf.st * pr.f2s),
          nf.ws * m * pr.gc,
          nf.ws * m * pr.gs};
}

// Column m of the projections: sum over the nodes of the integrands for n = m..n_max, with
// the Legendre columns produced on the fly (no table in memory: the loop is compute-bound).
// At the mirror node p and q pick up (-1)^(n-m), dp/dtheta -(-1)^(n-m): even and odd n - m
// get the sum and the difference of the two nodes' weights.
void project_order(int m, std::vector<LegendreColumn>& columns, const std::vector<EvalNode>& nodes,
                   std::vector<double> (&buf)[3], std::vector<double> (&acc)[4]) {
  const std::size_t len = buf[0].size() - static_cast<std::size_t>(m);
  for (std::vector<double>& a : acc) {
    std::fill(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(len), 0.0);
  }
  const double* p = buf[0].data();
  const double* dp = buf[1].data();
  const double* q = buf[2].data();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    columns[i].fill(buf[0].data(), buf[1].data(), buf[2].data());
    const OrderWeights d = order_weights(nodes[i].direct, m);
    const OrderWeights r = order_weights(nodes[i].mirror, m);
    const OrderWeights w[2] = {
        {d.rc + r.rc, d.rs + r.rs, d.tc - r.tc, d.ts - r.ts, d.gc + r.gc, d.gs + r.gs},
        {d.rc - r.rc, d.rs - r.rs, d.tc + r.tc, d.ts + r.ts, d.gc - r.gc, d.gs - r.gs}};
    for (std::size_t j = 0; j < len; ++j) {
      const OrderWeights& e = w[j & 1U];
      acc[0][j] += p[j] * e.rc;
      acc[1][j] += p[j] * e.rs;
      acc[2][j] += dp[j] * e.tc - q[j] * e.gs;
      acc[3][j] += dp[j] * e.ts + q[j] * e.gc;
    }
  }
}

ShellExpansion zero_expansion(int n_max) {
  ShellExpansion e{TriangularIndex(n_max), {}, {}, {}, {}};
  const std::size_t size = e.index.size();
  e.radial_cos.assign(size, 0.0);
  e.radial_sin.assign(size, 0.0);
  e.poloidal_cos.assign(size, 0.0);
  e.poloidal_sin.assign(size, 0.0);
  return e;
}

// Projections -> coefficients: divide by the norms of the basis functions,
// |Pbar cos m phi|^2 = N_m and |r grad (Pbar cos m phi)|^2 = n(n+1) N_m.
void normalize(ShellExpansion& e) {
  const TriangularIndex& index = e.index;
  for (int m = 0; m <= index.n_max(); ++m) {
    const double inv_norm = m == 0 ? 1.0 : 2.0;
    for (int n = m; n <= index.n_max(); ++n) {
      const std::size_t k = index(n, m);
      e.radial_cos[k] *= inv_norm;
      e.radial_sin[k] *= inv_norm;
      const double inv_pol = n == 0 ? 0.0 : inv_norm / (static_cast<double>(n) * (n + 1));
      e.poloidal_cos[k] *= inv_pol;
      e.poloidal_sin[k] *= inv_pol;
    }
  }
}

} // namespace

ShellExpansion expand_shell_magnetization(const std::vector<ShellSegmentSource>& segments,
                                          int n_max, double quadrature_scale, int n_threads) {
  const std::vector<Band> bands = make_bands(segments, n_max);
  const std::vector<EvalNode> nodes = make_nodes(bands, n_max, quadrature_scale);
  const NormalizedLegendre legendre(n_max);
  ShellExpansion total = zero_expansion(n_max);
  const int n_workers = std::max(1, std::min(n_threads, n_max + 1));

  // Orders are shared out round-robin (columns get shorter with m); each worker advances
  // every node's Legendre state through all orders and computes only its own columns.
  auto work = [&](int w) {
    std::vector<LegendreColumn> columns;
    columns.reserve(nodes.size());
    for (const EvalNode& node : nodes) {
      columns.emplace_back(legendre, node.theta);
    }
    const auto size = static_cast<std::size_t>(n_max) + 1;
    std::vector<double> buf[3] = {std::vector<double>(size), std::vector<double>(size),
                                  std::vector<double>(size)};
    std::vector<double> acc[4] = {std::vector<double>(size), std::vector<double>(size),
                                  std::vector<double>(size), std::vector<double>(size)};
    for (int m = 0; m <= n_max; ++m) {
      if (m % n_workers != w) {
        for (LegendreColumn& c : columns) {
          c.skip();
        }
        continue;
      }
      project_order(m, columns, nodes, buf, acc);
      const std::size_t c = total.index.column_start(m);
      for (std::size_t j = 0; j + static_cast<std::size_t>(m) < size; ++j) {
        total.radial_cos[c + j] = acc[0][j];
        total.radial_sin[c + j] = acc[1][j];
        total.poloidal_cos[c + j] = acc[2][j];
        total.poloidal_sin[c + j] = acc[3][j];
      }
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < n_workers; ++w) {
    threads.emplace_back(work, w);
  }
  work(0);
  for (std::thread& t : threads) {
    t.join();
  }
  normalize(total);
  return total;
}

} // namespace magfem
