#include "analytic/harmonic_model.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>

#include "core/constants.hpp"

namespace magfem {

namespace {

constexpr double kGeomTol = 1e-12; // relative, for "same radius", "at the origin", ...

[[noreturn]] void reject(const AnalyticMagnet& m, std::size_t i, const std::string& why) {
  throw std::invalid_argument("HarmonicModel: magnet '" +
                              (m.name.empty() ? "#" + std::to_string(i) : m.name) +
                              "' cannot be represented: " + why);
}

ShellSegmentSource segment_source(const AnalyticMagnet& m, std::size_t i, const SphericalSegment& s,
                                  double scale) {
  if (!(s.theta_min >= -kGeomTol && s.theta_max <= pi + kGeomTol && s.theta_min < s.theta_max)) {
    reject(m, i, "theta range must satisfy 0 <= theta_min < theta_max <= pi");
  }
  if (!(s.phi_min < s.phi_max && s.phi_max - s.phi_min <= 2 * pi * (1 + kGeomTol))) {
    reject(m, i, "phi range must satisfy phi_min < phi_max <= phi_min + 2 pi");
  }
  if (!std::isfinite(m.B_r)) {
    reject(m, i, "B_r is not finite");
  }
  ShellSegmentSource src{std::max(0.0, s.theta_min),
                         std::min(pi, s.theta_max),
                         s.phi_min,
                         s.phi_max,
                         Eigen::Vector3d::Zero(),
                         0.0};
  const double m0 = m.B_r / mu0 * m.magnetization.sign;
  if (m.magnetization.pattern == Magnetization::Pattern::parallel) {
    src.parallel = m0 * m.magnetization.direction.normalized();
  } else {
    if (m.magnetization.center.norm() > kGeomTol * scale) {
      reject(m, i, "radial magnetization must point away from the shell centre (the origin)");
    }
    src.radial = m0;
  }
  return src;
}

} // namespace

ShellArray to_shell_array(const std::vector<AnalyticMagnet>& magnets) {
  if (magnets.empty()) {
    throw std::invalid_argument("HarmonicModel: empty magnet list");
  }
  ShellArray shell;
  bool first = true;
  for (std::size_t i = 0; i < magnets.size(); ++i) {
    const AnalyticMagnet& m = magnets[i];
    const auto* s = std::get_if<SphericalSegment>(&m.shape);
    if (s == nullptr) {
      reject(m, i, "only SphericalSegment shapes (one spherical shell) are supported");
    }
    if (!(s->r_inner >= 0 && s->r_outer > s->r_inner)) {
      reject(m, i, "need 0 <= r_inner < r_outer");
    }
    if (first) {
      shell.r_inner = s->r_inner;
      shell.r_outer = s->r_outer;
      first = false;
    } else if (std::abs(s->r_inner - shell.r_inner) > kGeomTol * shell.r_outer ||
               std::abs(s->r_outer - shell.r_outer) > kGeomTol * shell.r_outer) {
      reject(m, i, "all segments must share r_inner and r_outer (one shell)");
    }
    if ((m.placement.rotation - Mat3::Identity()).norm() > kGeomTol ||
        m.placement.translation.norm() > kGeomTol * shell.r_outer) {
      reject(m, i, "segments must sit at the origin with identity rotation");
    }
    if (m.magnetization.pattern != Magnetization::Pattern::none) {
      shell.segments.push_back(segment_source(m, i, *s, shell.r_outer));
    }
  }
  return shell;
}

namespace {

HarmonicOptions checked(HarmonicOptions o, const ShellArray& shell) {
  if (o.n_max < 1) {
    throw std::invalid_argument("HarmonicModel: n_max must be >= 1, got " +
                                std::to_string(o.n_max));
  }
  if (!(o.quadrature_scale >= 1.0)) {
    throw std::invalid_argument("HarmonicModel: quadrature_scale must be >= 1");
  }
  if (o.permeable_radius && !(*o.permeable_radius > shell.r_outer)) {
    throw std::invalid_argument(
        "HarmonicModel: the permeable sphere (R_s = " + std::to_string(*o.permeable_radius) +
        " m) must enclose the magnets (r_outer = " + std::to_string(shell.r_outer) + " m)");
  }
  if (o.n_threads <= 0) {
    o.n_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  }
  return o;
}

std::optional<double> boundary_radius(const std::vector<PermeableSphere>& spheres) {
  if (spheres.empty()) {
    return std::nullopt;
  }
  if (spheres.size() > 1) {
    throw std::invalid_argument("HarmonicModel: at most one permeable sphere is supported, got " +
                                std::to_string(spheres.size()));
  }
  const PermeableSphere& s = spheres.front();
  if (s.center.norm() > kGeomTol * s.radius || !s.encloses) {
    throw std::invalid_argument("HarmonicModel: the permeable sphere must be centred at the "
                                "origin and enclose the magnets (an inner iron core is not "
                                "supported)");
  }
  return s.radius;
}

HarmonicOptions with_boundary(HarmonicOptions o, const std::vector<PermeableSphere>& spheres) {
  if (o.permeable_radius && !spheres.empty()) {
    throw std::invalid_argument("HarmonicModel: permeable sphere given twice (options and list)");
  }
  if (!spheres.empty()) {
    o.permeable_radius = boundary_radius(spheres);
  }
  return o;
}

} // namespace

HarmonicModel::HarmonicModel(const std::vector<AnalyticMagnet>& magnets, HarmonicOptions options)
    : HarmonicModel(to_shell_array(magnets), options) {}

HarmonicModel::HarmonicModel(const std::vector<AnalyticMagnet>& magnets,
                             const std::vector<PermeableSphere>& spheres, HarmonicOptions options)
    : HarmonicModel(to_shell_array(magnets), with_boundary(options, spheres)) {}

HarmonicModel::HarmonicModel(ShellArray shell, HarmonicOptions options)
    : options_(checked(options, shell)), r_inner_(shell.r_inner), r_outer_(shell.r_outer),
      segments_(std::move(shell.segments)),
      radial_(shell.r_inner, shell.r_outer, options_.permeable_radius), legendre_(options_.n_max) {
  const auto t0 = std::chrono::steady_clock::now();
  expansion_ = expand_shell_magnetization(segments_, options_.n_max, options_.quadrature_scale,
                                          options_.n_threads);
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Eigen::Vector3d HarmonicModel::magnetization_at(const Eigen::Vector3d& x) const {
  const double rho = x.norm();
  if (!(rho > r_inner_ && rho < r_outer_)) {
    return Eigen::Vector3d::Zero();
  }
  const double theta = std::acos(std::clamp(x.z() / rho, -1.0, 1.0));
  const double phi = std::atan2(x.y(), x.x());
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (const ShellSegmentSource& s : segments_) {
    // Half-open ranges, so that a point on a common face belongs to one segment only.
    const double p = s.phi_min + std::fmod(std::fmod(phi - s.phi_min, 2 * pi) + 2 * pi, 2 * pi);
    const bool in_theta = theta >= s.theta_min && (theta < s.theta_max || s.theta_max >= pi);
    if (in_theta && p < s.phi_max) {
      m += s.parallel + s.radial * x / rho;
    }
  }
  return m;
}

struct HarmonicModel::Group {
  double rho, theta;
  std::vector<std::size_t> points;
};

namespace {

struct Spherical {
  double rho, theta, phi;
};

Spherical to_spherical(const Eigen::Vector3d& x, double r_tiny) {
  double rho = x.norm();
  if (rho < r_tiny) {
    // At the centre the field is that of the degree-1 terms; rho -> tiny changes it by O(rho).
    return {r_tiny, 0.0, 0.0};
  }
  return {rho, std::atan2(std::hypot(x.x(), x.y()), x.z()), std::atan2(x.y(), x.x())};
}

// Per-order sums over the degree n at one (rho, theta): the field at any phi is then
//   H_rho   = -sum_m (rc_m cos m phi + rs_m sin m phi)
//   H_theta = -(1/rho) sum_m (tc_m cos m phi + ts_m sin m phi)
//   H_phi   = -(1/rho) sum_m (ps_m cos m phi - pc_m sin m phi)
struct OrderSums {
  std::vector<double> rc, rs, tc, ts, pc, ps;
  void resize(std::size_t n) {
    for (auto* v : {&rc, &rs, &tc, &ts, &pc, &ps}) {
      v->assign(n, 0.0);
    }
  }
};

// The Legendre columns are produced on the fly, one order at a time, into `col` (three
// buffers of n_max + 1).
void order_sums(const ShellExpansion& e, const NormalizedLegendre& legendre, double theta,
                const std::vector<RadialFactors>& f, std::vector<double> (&col)[3], OrderSums& s) {
  const TriangularIndex& index = e.index;
  const auto size = static_cast<std::size_t>(index.n_max()) + 1;
  s.resize(size);
  for (std::vector<double>& c : col) {
    c.resize(size);
  }
  LegendreColumn column(legendre, theta);
  for (int m = 0; m <= index.n_max(); ++m) {
    column.fill(col[0].data(), col[1].data(), col[2].data());
    const std::size_t begin = index.column_start(m);
    double rc = 0, rs = 0, tc = 0, ts = 0, pc = 0, ps = 0;
    for (int n = m; n <= index.n_max(); ++n) {
      const auto j = static_cast<std::size_t>(n - m);
      const std::size_t k = begin + j;
      const RadialFactors& r = f[static_cast<std::size_t>(n)];
      const double c = r.alpha * e.radial_cos[k] + r.beta * e.poloidal_cos[k];
      const double sn = r.alpha * e.radial_sin[k] + r.beta * e.poloidal_sin[k];
      const double dc = r.d_alpha * e.radial_cos[k] + r.d_beta * e.poloidal_cos[k];
      const double ds = r.d_alpha * e.radial_sin[k] + r.d_beta * e.poloidal_sin[k];
      rc += col[0][j] * dc;
      rs += col[0][j] * ds;
      tc += col[1][j] * c;
      ts += col[1][j] * sn;
      pc += col[2][j] * c;
      ps += col[2][j] * sn;
    }
    const auto mm = static_cast<std::size_t>(m);
    s.rc[mm] = rc;
    s.rs[mm] = rs;
    s.tc[mm] = tc;
    s.ts[mm] = ts;
    s.pc[mm] = m * pc;
    s.ps[mm] = m * ps;
  }
}

Eigen::Vector3d field_at_phi(const OrderSums& s, double rho, double theta, double phi) {
  double h_rho = 0, h_theta = 0, h_phi = 0;
  const double c1 = std::cos(phi), s1 = std::sin(phi);
  double cm = 1.0, sm = 0.0; // cos(m phi), sin(m phi) by rotation
  for (std::size_t m = 0; m < s.rc.size(); ++m) {
    h_rho += s.rc[m] * cm + s.rs[m] * sm;
    h_theta += s.tc[m] * cm + s.ts[m] * sm;
    h_phi += s.ps[m] * cm - s.pc[m] * sm;
    const double next = cm * c1 - sm * s1;
    sm = sm * c1 + cm * s1;
    cm = next;
  }
  h_rho = -h_rho;
  h_theta = -h_theta / rho;
  h_phi = -h_phi / rho;
  const double st = std::sin(theta), ct = std::cos(theta);
  const Eigen::Vector3d e_rho(st * c1, st * s1, ct);
  const Eigen::Vector3d e_theta(ct * c1, ct * s1, -st);
  const Eigen::Vector3d e_phi(-s1, c1, 0.0);
  return h_rho * e_rho + h_theta * e_theta + h_phi * e_phi;
}

} // namespace

void HarmonicModel::evaluate_group(const Group& group, const std::vector<Eigen::Vector3d>& x,
                                   std::vector<Eigen::Vector3d>& out) const {
  thread_local std::vector<double> columns[3];
  thread_local std::vector<RadialFactors> factors;
  thread_local OrderSums sums;
  radial_.evaluate(group.rho, options_.n_max, factors);
  order_sums(expansion_, legendre_, group.theta, factors, columns, sums);
  const double r_tiny = 1e-12 * r_outer_;
  for (std::size_t i : group.points) {
    const Spherical p = to_spherical(x[i], r_tiny);
    const Eigen::Vector3d h = field_at_phi(sums, group.rho, p.theta, p.phi);
    out[i] = mu0 * (h + magnetization_at(x[i]));
  }
}

std::vector<Eigen::Vector3d> HarmonicModel::B(const std::vector<Eigen::Vector3d>& x) const {
  const double r_tiny = 1e-12 * r_outer_;
  std::vector<Spherical> sph(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    sph[i] = to_spherical(x[i], r_tiny);
    if (options_.permeable_radius && sph[i].rho > *options_.permeable_radius * (1 + kGeomTol)) {
      throw std::domain_error("HarmonicModel::B: point at rho = " + std::to_string(sph[i].rho) +
                              " m lies inside the permeable boundary material (R_s = " +
                              std::to_string(*options_.permeable_radius) + " m)");
    }
  }
  // Group points that share (rho, theta) to round-off: their degree sums are the same.
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return sph[a].rho != sph[b].rho ? sph[a].rho < sph[b].rho : sph[a].theta < sph[b].theta;
  });
  std::vector<Group> groups;
  for (std::size_t i : order) {
    const Spherical& p = sph[i];
    if (groups.empty() || std::abs(p.rho - groups.back().rho) > kGeomTol * p.rho ||
        std::abs(p.theta - groups.back().theta) > kGeomTol) {
      groups.push_back({p.rho, p.theta, {}});
    }
    groups.back().points.push_back(i);
  }
  // Sorting by rho first can interleave thetas of nearly equal rho; merge groups again.
  std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) {
    return a.theta != b.theta ? a.theta < b.theta : a.rho < b.rho;
  });
  std::vector<Group> merged;
  for (Group& g : groups) {
    if (!merged.empty() && std::abs(g.rho - merged.back().rho) <= kGeomTol * g.rho &&
        std::abs(g.theta - merged.back().theta) <= kGeomTol) {
      merged.back().points.insert(merged.back().points.end(), g.points.begin(), g.points.end());
    } else {
      merged.push_back(std::move(g));
    }
  }

  std::vector<Eigen::Vector3d> out(x.size(), Eigen::Vector3d::Zero());
  std::atomic<std::size_t> next{0};
  auto work = [&]() {
    for (std::size_t g = next++; g < merged.size(); g = next++) {
      evaluate_group(merged[g], x, out);
    }
  };
  const int n_workers =
      std::max(1, std::min<int>(options_.n_threads, static_cast<int>(merged.size())));
  std::vector<std::thread> threads;
  for (int w = 1; w < n_workers; ++w) {
    threads.emplace_back(work);
  }
  work();
  for (std::thread& t : threads) {
    t.join();
  }
  return out;
}

std::vector<Eigen::Vector3d> HarmonicModel::H(const std::vector<Eigen::Vector3d>& x) const {
  std::vector<Eigen::Vector3d> h = B(x);
  for (std::size_t i = 0; i < x.size(); ++i) {
    h[i] = h[i] / mu0 - magnetization_at(x[i]);
  }
  return h;
}

Eigen::Vector3d HarmonicModel::B(const Eigen::Vector3d& x) const {
  return B(std::vector<Eigen::Vector3d>{x}).front();
}

} // namespace magfem
