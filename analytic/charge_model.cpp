#include "analytic/charge_model.hpp"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "core/constants.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

// Splits below this size relative to the face are pointless (the observation point sits on the
// face, where the field itself is discontinuous).
constexpr double min_radius_fraction = 1e-9;
constexpr int max_depth = 80;

// H of point charges at x, without 1/4pi. A charge at x contributes nothing. The kernel is
// 3/4 of the charge model's time (the 12-coil actuator's 7 x 7 torque-constant grid), bound
// by square roots and divisions: with SSE2 (every x86-64) two charges share each sqrtpd and
// divpd.
double kernel_factor(double q, double r2) {
  return r2 > 0 ? q / (r2 * std::sqrt(r2)) : 0.0;
}

void add_kernel(const PointCharge* begin, const PointCharge* end, const Vec3& x, Vec3& sum) {
  const std::ptrdiff_t n = end - begin;
  std::ptrdiff_t i = 0;
  double hx = 0, hy = 0, hz = 0;
#ifdef __SSE2__
  __m128d sx = _mm_setzero_pd(), sy = _mm_setzero_pd(), sz = _mm_setzero_pd();
  const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  for (; i + 2 <= n; i += 2) {
    const PointCharge& a = begin[i];
    const PointCharge& b = begin[i + 1];
    const __m128d dx = _mm_sub_pd(_mm_set1_pd(x[0]), _mm_set_pd(b.x[0], a.x[0]));
    const __m128d dy = _mm_sub_pd(_mm_set1_pd(x[1]), _mm_set_pd(b.x[1], a.x[1]));
    const __m128d dz = _mm_sub_pd(_mm_set1_pd(x[2]), _mm_set_pd(b.x[2], a.x[2]));
    const __m128d r2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
    const __m128d apart = _mm_cmpgt_pd(r2, zero);
    // r2 = 0: 0 / 1 instead of q / 0.
    const __m128d q = _mm_and_pd(apart, _mm_set_pd(b.q, a.q));
    const __m128d r2_safe = _mm_or_pd(_mm_and_pd(apart, r2), _mm_andnot_pd(apart, one));
    const __m128d f = _mm_div_pd(q, _mm_mul_pd(r2_safe, _mm_sqrt_pd(r2_safe)));
    sx = _mm_add_pd(sx, _mm_mul_pd(f, dx));
    sy = _mm_add_pd(sy, _mm_mul_pd(f, dy));
    sz = _mm_add_pd(sz, _mm_mul_pd(f, dz));
  }
  double lanes[2];
  _mm_storeu_pd(lanes, sx);
  hx = lanes[0] + lanes[1];
  _mm_storeu_pd(lanes, sy);
  hy = lanes[0] + lanes[1];
  _mm_storeu_pd(lanes, sz);
  hz = lanes[0] + lanes[1];
#endif
  for (; i < n; ++i) {
    const PointCharge& p = begin[i];
    const double dx = x[0] - p.x[0], dy = x[1] - p.x[1], dz = x[2] - p.x[2];
    const double f = kernel_factor(p.q, dx * dx + dy * dy + dz * dz);
    hx += f * dx;
    hy += f * dy;
    hz += f * dz;
  }
  sum += Vec3(hx, hy, hz);
}

// Biot-Savart sum without mu0/4pi: sum j x (x - x') / |x - x'|^3 (gives B/mu0 times 4 pi).
void add_current_kernel(const PointCurrent* begin, const PointCurrent* end, const Vec3& x,
                        Vec3& sum) {
  Vec3 acc = Vec3::Zero();
  for (const PointCurrent* p = begin; p != end; ++p) {
    const Vec3 d = x - p->x;
    const double r2 = d.squaredNorm();
    if (r2 == 0)
      continue;
    acc += p->j.cross(d) / (r2 * std::sqrt(r2));
  }
  sum += acc;
}

} // namespace

ChargeModel::ChargeModel(std::vector<AnalyticMagnet> magnets, std::vector<PermeableSphere> spheres,
                         ChargeModelOptions options)
    : magnets_(std::move(magnets)), spheres_(std::move(spheres)), options_(options),
      surface_rule_(options.gauss_order), volume_rule_(options.volume_gauss_order) {
  if (!(options_.tolerance > 0))
    throw std::invalid_argument("ChargeModel: tolerance must be positive");
  check_spheres();
  const std::vector<std::vector<int>> chains =
      image_chains(static_cast<int>(spheres_.size()), options_.image_order);
  for (const AnalyticMagnet& m : magnets_) {
    // With permeable spheres the originals stay charges: each original node then pairs with
    // its image node exactly, so the boundary condition holds to round-off, not to tolerance.
    const bool as_current = options_.radial_as_currents && spheres_.empty() &&
                            m.magnetization.pattern == Magnetization::Pattern::radial;
    as_current_.push_back(as_current);
    if (as_current)
      for (const ChargeDomain& d : current_domains(m))
        build_source(d, ImageMap{}, true);
    // Images are always charges (inversion preserves charges, not currents).
    for (const ChargeDomain& d : charge_domains(m)) {
      if (!as_current)
        build_source(d, ImageMap{}, false);
      for (const auto& chain : chains) {
        std::vector<Inversion> invs;
        for (int s : chain)
          invs.push_back({spheres_[s].center, spheres_[s].radius});
        build_source(d, ImageMap(std::move(invs)), false);
      }
    }
  }
  add_compensation();
}

// Imaging is valid only if every magnet lies wholly on the air side of every boundary
// (touching allowed); checked on a grid of points over every face and volume, edges included.
void ChargeModel::check_spheres() const {
  for (const PermeableSphere& sphere : spheres_) {
    if (!(sphere.radius > 0))
      throw std::invalid_argument("ChargeModel: permeable sphere radius must be positive");
    const double slack = 1e-9 * sphere.radius;
    for (const AnalyticMagnet& m : magnets_)
      for (const ChargeDomain& d : charge_domains(m)) {
        const int n = d.dim == 2 ? 9 : 5;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            for (int k = 0; k < (d.dim == 2 ? 1 : n); ++k) {
              std::array<double, 3> u{};
              const int idx[3] = {i, j, k};
              for (int a = 0; a < d.dim; ++a)
                u[a] = d.box.lo[a] + (d.box.hi[a] - d.box.lo[a]) * idx[a] / (n - 1);
              const double r = (d.point(u) - sphere.center).norm();
              if (sphere.encloses ? r > sphere.radius + slack : r < sphere.radius - slack)
                throw std::invalid_argument("ChargeModel: magnet '" + m.name +
                                            "' is not on the air side of a permeable sphere");
            }
      }
  }
}

void ChargeModel::build_source(const ChargeDomain& domain, const ImageMap& map, bool current) {
  Source s;
  s.domain = domain;
  s.map = map;
  s.current = current;
  // A volume box of radius r containing the observation point adds at most about
  // rho_m r ~ M0 r / rho to H (the 1/r^2 kernel is integrable), so volumes stop splitting at
  // a fraction of the tolerance; surfaces only at round-off scale (a point on a face).
  const double fraction =
      domain.dim == 3 ? std::min(0.1 * options_.tolerance, 1e-3) : min_radius_fraction;
  s.min_radius = fraction * box_extent(domain, domain.box).radius;
  s.ratio = acceptance_ratio(options_.tolerance, rule_of(s).size());
  for (const ParamBox& b : root_boxes(domain, options_.max_angle))
    s.roots.push_back(build_node(s, b, 0));
  sources_.push_back(std::move(s));
}

int ChargeModel::build_node(Source& s, const ParamBox& box, int depth) {
  const BoxExtent e = box_extent(s.domain, box);
  const int index = static_cast<int>(s.nodes.size());
  TreeNode node;
  node.box = box;
  node.centre = e.centre;
  node.radius = e.radius;
  node.axis = e.longest_axis;
  if (s.current) {
    node.begin = static_cast<int>(s.currents.size());
    s.domain.current_quadrature(box, rule_of(s), s.currents);
    node.end = static_cast<int>(s.currents.size());
  } else {
    node.begin = static_cast<int>(s.charges.size());
    s.domain.quadrature(box, rule_of(s), s.charges);
    if (!s.map.is_identity())
      for (int i = node.begin; i < static_cast<int>(s.charges.size()); ++i)
        s.charges[i] = s.map.apply(s.charges[i]);
    node.end = static_cast<int>(s.charges.size());
  }
  s.nodes.push_back(node);
  if (depth < options_.cached_depth) {
    const auto halves = split_box(box, e.longest_axis);
    const int first = build_node(s, halves[0], depth + 1);
    const int second = build_node(s, halves[1], depth + 1);
    s.nodes[index].child[0] = first;
    s.nodes[index].child[1] = second;
  }
  return index;
}

// An inner permeable sphere (encloses = false) is iron: the flux entering it must vanish, so
// the net image charge inside it is cancelled by a point charge at its centre (which keeps
// its surface an equipotential). An enclosing sphere needs none: the region inside is free
// of such a charge by construction.
void ChargeModel::add_compensation() {
  std::vector<double> net(spheres_.size(), 0.0);
  for (const Source& s : sources_) {
    if (s.map.is_identity())
      continue;
    const Inversion& last = s.map.chain().back();
    for (std::size_t k = 0; k < spheres_.size(); ++k)
      if (!spheres_[k].encloses && spheres_[k].center == last.centre &&
          spheres_[k].radius == last.radius) {
        // Sum over the finest precomputed level: leaves of the cached tree.
        for (const TreeNode& n : s.nodes)
          if (n.child[0] < 0)
            for (int i = n.begin; i < n.end; ++i)
              net[k] += s.charges[i].q;
        break;
      }
  }
  for (std::size_t k = 0; k < spheres_.size(); ++k)
    if (!spheres_[k].encloses && net[k] != 0)
      point_charges_.push_back({spheres_[k].center, -net[k]});
}

const GaussRule& ChargeModel::rule_of(const Source& s) const {
  return s.domain.dim == 3 ? volume_rule_ : surface_rule_;
}

bool ChargeModel::far_enough(const Source& s, const Vec3& centre, double radius,
                             const Vec3& x_pre) {
  return radius <= s.min_radius || (x_pre - centre).norm() >= s.ratio * radius;
}

void ChargeModel::add_leaf(const Source& s, int begin, int end, const Vec3& x, Accumulator& acc) {
  if (s.current)
    add_current_kernel(s.currents.data() + begin, s.currents.data() + end, x, acc.h_currents);
  else
    add_kernel(s.charges.data() + begin, s.charges.data() + end, x, acc.h_charges);
}

void ChargeModel::accumulate(const Source& s, int node, const Vec3& x, const Vec3& x_pre,
                             Accumulator& acc) const {
  const TreeNode& n = s.nodes[node];
  if (far_enough(s, n.centre, n.radius, x_pre)) {
    add_leaf(s, n.begin, n.end, x, acc);
    return;
  }
  if (n.child[0] >= 0) {
    accumulate(s, n.child[0], x, x_pre, acc);
    accumulate(s, n.child[1], x, x_pre, acc);
    return;
  }
  accumulate_box(s, n.box, n.axis, options_.cached_depth, x, x_pre, acc);
}

// Near field below the cached levels: split `box` and recurse without storing.
void ChargeModel::accumulate_box(const Source& s, const ParamBox& box, int axis, int depth,
                                 const Vec3& x, const Vec3& x_pre, Accumulator& acc) const {
  for (const ParamBox& half : split_box(box, axis)) {
    const BoxExtent e = box_extent(s.domain, half);
    if (depth + 1 < max_depth && !far_enough(s, e.centre, e.radius, x_pre)) {
      accumulate_box(s, half, e.longest_axis, depth + 1, x, x_pre, acc);
      continue;
    }
    if (s.current) {
      acc.currents.clear();
      s.domain.current_quadrature(half, rule_of(s), acc.currents);
      add_current_kernel(acc.currents.data(), acc.currents.data() + acc.currents.size(), x,
                         acc.h_currents);
      continue;
    }
    acc.charges.clear();
    s.domain.quadrature(half, rule_of(s), acc.charges);
    if (!s.map.is_identity())
      for (PointCharge& p : acc.charges)
        p = s.map.apply(p);
    add_kernel(acc.charges.data(), acc.charges.data() + acc.charges.size(), x, acc.h_charges);
  }
}

ChargeModel::Accumulator ChargeModel::evaluate(const Vec3& x) const {
  Accumulator acc;
  acc.charges.reserve(std::max(surface_rule_.size() * surface_rule_.size(),
                               volume_rule_.size() * volume_rule_.size() * volume_rule_.size()));
  acc.currents.reserve(surface_rule_.size() * surface_rule_.size());
  for (const Source& s : sources_) {
    const Vec3 x_pre = s.map.is_identity() ? x : s.map.preimage(x);
    for (int root : s.roots)
      accumulate(s, root, x, x_pre, acc);
  }
  add_kernel(point_charges_.data(), point_charges_.data() + point_charges_.size(), x,
             acc.h_charges);
  acc.h_charges /= 4 * pi;
  acc.h_currents /= 4 * pi;
  return acc;
}

// Magnetization of the magnets containing x, split by their model (charges or currents).
std::pair<Vec3, Vec3> ChargeModel::split_magnetization(const Vec3& x) const {
  Vec3 by_charges = Vec3::Zero(), by_currents = Vec3::Zero();
  for (std::size_t i = 0; i < magnets_.size(); ++i) {
    const AnalyticMagnet& a = magnets_[i];
    if (a.magnetization.active() && magnet_contains(a, x))
      (as_current_[i] ? by_currents : by_charges) += (a.B_r / mu0) * a.magnetization.unit_at(x);
  }
  return {by_charges, by_currents};
}

// Charges give H directly; currents give B = mu0 h_currents, which includes M inside the
// current-modelled magnets: H = h_charges + h_currents - M_currents, B = mu0 (h_charges +
// h_currents + M_charges).
Vec3 ChargeModel::H(const Vec3& x) const {
  const Accumulator acc = evaluate(x);
  return acc.h_charges + acc.h_currents - split_magnetization(x).second;
}

Vec3 ChargeModel::B(const Vec3& x) const {
  const Accumulator acc = evaluate(x);
  return mu0 * (acc.h_charges + acc.h_currents + split_magnetization(x).first);
}

Vec3 ChargeModel::magnetization(const Vec3& x) const {
  Vec3 m = Vec3::Zero();
  for (const AnalyticMagnet& a : magnets_)
    if (a.magnetization.active() && magnet_contains(a, x))
      m += (a.B_r / mu0) * a.magnetization.unit_at(x);
  return m;
}

template <class F>
std::vector<Vec3> ChargeModel::parallel_map(const std::vector<Vec3>& xs, F f) const {
  std::vector<Vec3> out(xs.size());
  int n = options_.n_threads > 0 ? options_.n_threads
                                 : static_cast<int>(std::thread::hardware_concurrency());
  n = std::clamp(n, 1, std::max(1, static_cast<int>(xs.size())));
  // Interleaved assignment balances near-field-heavy points across threads.
  auto work = [&](int t) {
    for (std::size_t i = t; i < xs.size(); i += n)
      out[i] = f(xs[i]);
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < n; ++t)
    threads.emplace_back(work, t);
  work(0);
  for (std::thread& th : threads)
    th.join();
  return out;
}

std::vector<Vec3> ChargeModel::H(const std::vector<Vec3>& xs) const {
  return parallel_map(xs, [this](const Vec3& x) { return H(x); });
}

std::vector<Vec3> ChargeModel::B(const std::vector<Vec3>& xs) const {
  return parallel_map(xs, [this](const Vec3& x) { return B(x); });
}

} // namespace magfem
