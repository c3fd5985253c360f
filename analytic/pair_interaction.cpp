#include "analytic/pair_interaction.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "core/constants.hpp"
#include "analytic/charge_source.hpp"
#include "analytic/gauss_error.hpp"
#include "analytic/mirror_symmetry.hpp"
#include "analytic/surface_patch_order.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

// box_extent samples a 3^dim grid of the box's image; a curved box bulges a little beyond
// it, so radii are enlarged by this factor before the distance tests.
constexpr double radius_margin = 1.1;
// Boxes below this fraction of their face's size are not split further (touching faces).
constexpr double min_radius_fraction = 1e-4;
constexpr int min_order = 2;
constexpr double coarse_factor = 100; // tolerance of the run that estimates the error
// r^2 floor (m^2) of coincident nodes: far below any node spacing, and q / r^3 stays finite.
constexpr double coincident_r2 = 1e-200;

struct PairBox {
  const ChargeDomain* domain;
  ParamBox box;
  Vec3 centre;
  double radius;
  int axis;
  double min_radius;  // of its face
  double half_angle;  // largest half-width of its angular parameters (radians)
  SurfacePatch patch; // affine model (surfaces, when patch orders are on; else invalid)
};

PairBox make_box(const ChargeDomain* d, const ParamBox& b, double min_radius, bool patch) {
  // The surface patch model reuses the extent's samples (their sines and cosines dominate the
  // cost of a box).
  std::array<Vec3, 9> grid;
  patch = patch && d->dim == 2;
  const BoxExtent e = box_extent(*d, b, patch ? &grid : nullptr);
  const std::array<bool, 3> angular = angular_parameters(*d);
  double h = 0;
  for (int a = 0; a < 3; ++a)
    if (angular[a])
      h = std::max(h, 0.5 * (b.hi[a] - b.lo[a]));
  return {d,
          b,
          e.centre,
          radius_margin * e.radius,
          e.longest_axis,
          min_radius,
          h,
          patch ? surface_patch(grid) : SurfacePatch{}};
}

struct Context {
  double tolerance;
  int max_order;
  bool patch_orders;
  Vec3 torque_point;
  std::vector<GaussRule> rules; // index = order
};

struct Tally {
  ForceTorque ft;
  long pairs = 0, kernels = 0;
};

// Quadrature points of recently used (box, order), kept as arrays in a small direct-mapped
// table per side and thread. The dual-tree recursion revisits a box with many partners (and
// a box's children with each partner of its parent), and generating the nodes (sines,
// cosines and the magnetization per node) cost about as much as the kernel sums of a pair.
struct QuadratureNodes {
  const ChargeDomain* domain = nullptr;
  ParamBox box;
  int order = -1;
  std::vector<PointCharge> charges;
  std::vector<double> x, y, z, q;
};

class QuadratureCache {
public:
  const QuadratureNodes& get(const PairBox& b, int n, const GaussRule& rule) {
    QuadratureNodes& e = slots_[slot_of(b, n)];
    if (e.domain == b.domain && e.order == n && e.box.lo == b.box.lo && e.box.hi == b.box.hi)
      return e;
    e.domain = b.domain, e.box = b.box, e.order = n;
    e.charges.clear();
    b.domain->quadrature(b.box, rule, e.charges);
    e.x.clear(), e.y.clear(), e.z.clear(), e.q.clear();
    for (const PointCharge& p : e.charges)
      e.x.push_back(p.x[0]), e.y.push_back(p.x[1]), e.z.push_back(p.x[2]), e.q.push_back(p.q);
    return e;
  }

private:
  static constexpr std::size_t n_slots = 128;
  static std::size_t slot_of(const PairBox& b, int n) {
    std::uint64_t h = reinterpret_cast<std::uintptr_t>(b.domain) + static_cast<std::uint64_t>(n);
    for (int a = 0; a < 3; ++a)
      for (double v : {b.box.lo[a], b.box.hi[a]})
        h = (h ^ std::bit_cast<std::uint64_t>(v)) * 0x9e3779b97f4a7c15ull;
    return static_cast<std::size_t>(h >> 32) % n_slots;
  }
  std::array<QuadratureNodes, n_slots> slots_;
};

struct Scratch {
  QuadratureCache a_nodes, b_nodes; // one per side: an entry in use is never evicted
  std::vector<double> kernel;       // q_B / r^3 per node of B (capacity kept across pairs)
};

void integrate_pair(const Context& c, const PairBox& a, int na, const PairBox& b, int nb,
                    Scratch& w, Tally& t) {
  using Array = Eigen::ArrayXd;
  using Map = Eigen::Map<const Array>;
  const QuadratureNodes& sa = w.a_nodes.get(a, na, c.rules[na]);
  const QuadratureNodes& sb = w.b_nodes.get(b, nb, c.rules[nb]);
  const Eigen::Index m = static_cast<Eigen::Index>(sb.q.size());
  const Map bx(sb.x.data(), m), by(sb.y.data(), m), bz(sb.z.data(), m), bq(sb.q.data(), m);
  // Whole-array expressions over B's nodes: Eigen vectorizes them (sqrt, division and the
  // sums), where a scalar loop is not (one floating-point sum cannot be reordered, and
  // std::sqrt keeps errno). The summation order is fixed, so results do not depend on threads.
  w.kernel.resize(static_cast<std::size_t>(m));
  Eigen::Map<Array> kernel(w.kernel.data(), m);
  Vec3 f_sum = Vec3::Zero(), t_sum = Vec3::Zero();
  for (std::size_t i = 0; i < sa.q.size(); ++i) {
    if (sa.q[i] == 0)
      continue;
    const double px = sa.x[i], py = sa.y[i], pz = sa.z[i];
    // Coincident nodes (touching faces) carry no resolvable force: their r^2 is raised to a
    // floor whose finite kernel then multiplies an offset of exactly 0 (a select would not
    // vectorize).
    const auto r2 =
        ((px - bx).square() + (py - by).square() + (pz - bz).square()).max(coincident_r2);
    kernel = bq / (r2 * r2.sqrt());
    const Vec3 f = sa.q[i] * Vec3((kernel * (px - bx)).sum(), (kernel * (py - by)).sum(),
                                  (kernel * (pz - bz)).sum());
    f_sum += f;
    t_sum += (Vec3(px, py, pz) - c.torque_point).cross(f);
  }
  const double k = mu0 / (4 * pi);
  t.ft.force += k * f_sum;
  t.ft.torque += k * t_sum;
  ++t.pairs;
  t.kernels += static_cast<long>(sa.q.size() * sb.q.size());
}

std::array<PairBox, 2> halves(const Context& c, const PairBox& x) {
  const auto h = split_box(x.box, x.axis);
  return {make_box(x.domain, h[0], x.min_radius, c.patch_orders),
          make_box(x.domain, h[1], x.min_radius, c.patch_orders)};
}

// Orders of the two sides: the bounding-sphere rule, or where both boxes are surfaces whose
// affine models are trusted, the singularity's complex offset (surface_patch_order.hpp),
// whichever is lower (both are a priori bounds of the same error). Both sides take the same
// rule: the bounding-sphere order of one side grows with the other's radius, so mixing the
// rules would split the small side where the large one should be.
std::array<int, 2> pair_orders(const Context& c, const PairBox& a, const PairBox& b) {
  const double d = (a.centre - b.centre).norm();
  const double rho_a = (d - b.radius) / a.radius, rho_b = (d - a.radius) / b.radius;
  const int na = gauss_order(c.tolerance, rho_a, a.half_angle, min_order, c.max_order);
  const int nb = gauss_order(c.tolerance, rho_b, b.half_angle, min_order, c.max_order);
  if (!c.patch_orders || (na == min_order && nb == min_order))
    return {na, nb};
  const std::optional<double> pa = patch_pair_rho(a.patch, b.patch);
  const std::optional<double> pb = pa ? patch_pair_rho(b.patch, a.patch) : std::nullopt;
  if (!pb)
    return {na, nb};
  return {std::min(na, gauss_order(c.tolerance, *pa, a.half_angle, min_order, c.max_order)),
          std::min(nb, gauss_order(c.tolerance, *pb, b.half_angle, min_order, c.max_order))};
}

// Dual-tree recursion: integrate the pair when both orders fit, otherwise split the side that
// needs the higher order (the larger box when both need the same; both when tied).
void interact(const Context& c, const PairBox& a, const PairBox& b, Scratch& w, Tally& t) {
  const auto [na, nb] = pair_orders(c, a, b);
  if (na <= c.max_order && nb <= c.max_order) {
    integrate_pair(c, a, na, b, nb, w, t);
    return;
  }
  const bool a_splits = a.radius > a.min_radius, b_splits = b.radius > b.min_radius;
  if (!a_splits && !b_splits) {
    integrate_pair(c, a, c.max_order, b, c.max_order, w, t);
    return;
  }
  // Symmetric in a and b (a full tie splits both), so that swapping the groups integrates the
  // same point pairs: action = reaction then holds to round-off.
  bool split_a = na > nb || (na == nb && a.radius > b.radius);
  bool split_b = nb > na || (na == nb && b.radius > a.radius);
  if (!split_a && !split_b)
    split_a = split_b = true;
  split_a = split_a && a_splits;
  split_b = split_b && b_splits;
  if (!split_a && !split_b)
    (a_splits ? split_a : split_b) = true;
  if (split_a && split_b) {
    for (const PairBox& ha : halves(c, a))
      for (const PairBox& hb : halves(c, b))
        interact(c, ha, hb, w, t);
  } else if (split_a) {
    for (const PairBox& h : halves(c, a))
      interact(c, h, b, w, t);
  } else {
    for (const PairBox& h : halves(c, b))
      interact(c, a, h, w, t);
  }
}

// The domains of all magnets, and the index of each domain's magnet.
std::vector<ChargeDomain> domains_of(const std::vector<AnalyticMagnet>& magnets,
                                     std::vector<int>& magnet_of) {
  std::vector<ChargeDomain> out;
  for (std::size_t m = 0; m < magnets.size(); ++m)
    for (const ChargeDomain& d : charge_domains(magnets[m])) {
      out.push_back(d);
      magnet_of.push_back(static_cast<int>(m));
    }
  return out;
}

// The root boxes of all domains, and the index of each root's magnet.
std::vector<PairBox> roots_of(const std::vector<ChargeDomain>& domains,
                              const std::vector<int>& magnet_of_domain, bool patch,
                              std::vector<int>& magnet_of) {
  std::vector<PairBox> out;
  for (std::size_t i = 0; i < domains.size(); ++i) {
    const ChargeDomain& d = domains[i];
    const double min_r = min_radius_fraction * box_extent(d, d.box).radius;
    for (const ParamBox& b : root_boxes(d, pi / 4)) {
      out.push_back(make_box(&d, b, min_r, patch));
      magnet_of.push_back(magnet_of_domain[i]);
    }
  }
  return out;
}

// A root pair to integrate; if image_sign != 0 its mirror pair (mirror_symmetry.hpp) is not
// integrated but added as the mirrored result times image_sign.
struct RootPair {
  std::size_t a, b;
  double image_sign = 0;
};

std::vector<RootPair> plan_root_pairs(const std::vector<int>& magnet_a,
                                      const std::vector<int>& magnet_b,
                                      const std::optional<MirrorSymmetry>& mirror) {
  std::vector<RootPair> plan;
  for (std::size_t a = 0; a < magnet_a.size(); ++a)
    for (std::size_t b = 0; b < magnet_b.size(); ++b) {
      if (!mirror) {
        plan.push_back({a, b});
        continue;
      }
      const std::pair<int, int> pair{magnet_a[a], magnet_b[b]};
      const std::pair<int, int> image{mirror->image_on[pair.first], mirror->image_by[pair.second]};
      if (image == pair)
        plan.push_back({a, b}); // its own mirror image: integrated in full
      else if (pair < image)
        plan.push_back({a, b, mirror->sign_on[pair.first] * mirror->sign_by[pair.second]});
      // else: the image pair is in the plan and stands for this one
    }
  return plan;
}

Tally run(const std::vector<PairBox>& ra, const std::vector<PairBox>& rb,
          const std::vector<RootPair>& plan, const std::optional<MirrorSymmetry>& mirror,
          const Context& c, int n_threads) {
  // Root pairs are independent: share them among threads, sum in pair order (deterministic).
  const std::size_t n = plan.size();
  std::vector<Tally> results(n);
  std::mutex mutex;
  std::size_t next = 0;
  auto work = [&] {
    Scratch w;
    for (;;) {
      std::size_t i;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= n)
          return;
        i = next++;
      }
      interact(c, ra[plan[i].a], rb[plan[i].b], w, results[i]);
    }
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < n_threads; ++k)
    threads.emplace_back(work);
  work();
  for (std::thread& th : threads)
    th.join();
  Tally total;
  for (std::size_t i = 0; i < n; ++i) {
    const Tally& r = results[i];
    total.ft.force += r.ft.force;
    total.ft.torque += r.ft.torque;
    if (plan[i].image_sign != 0) {
      // About a point of the plane: F -> s S F, T -> -s S T (the torque is an axial vector).
      total.ft.force += plan[i].image_sign * mirror->reflect(r.ft.force);
      total.ft.torque -= plan[i].image_sign * mirror->reflect(r.ft.torque);
    }
    total.pairs += r.pairs;
    total.kernels += r.kernels;
  }
  return total;
}

} // namespace

PairInteraction pair_interaction(const std::vector<AnalyticMagnet>& on,
                                 const std::vector<AnalyticMagnet>& by, const Vec3& torque_point,
                                 const PairInteractionOptions& options) {
  if (!(options.tolerance > 0 && options.tolerance < 1))
    throw std::invalid_argument("pair_interaction: tolerance must lie in (0, 1)");
  std::vector<int> domain_a, domain_b, magnet_a, magnet_b;
  const std::vector<ChargeDomain> da = domains_of(on, domain_a), db = domains_of(by, domain_b);
  const std::vector<PairBox> ra = roots_of(da, domain_a, options.patch_orders, magnet_a),
                             rb = roots_of(db, domain_b, options.patch_orders, magnet_b);
  const std::optional<MirrorSymmetry> mirror =
      options.mirror_symmetry ? find_mirror_symmetry(on, by, torque_point) : std::nullopt;
  const std::vector<RootPair> plan = plan_root_pairs(magnet_a, magnet_b, mirror);
  const int n_threads = options.n_threads > 0
                            ? options.n_threads
                            : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  Context c{options.tolerance,
            std::max(min_order, options.max_order),
            options.patch_orders,
            torque_point,
            {}};
  for (int n = 0; n <= c.max_order; ++n)
    c.rules.emplace_back(std::max(1, n));
  const Tally t = run(ra, rb, plan, mirror, c, n_threads);
  PairInteraction out;
  out.on_A = t.ft;
  // Accuracy: the same at 100 x the tolerance, whose difference from the result bounds the
  // coarser one's error in practice (geometric convergence) and so overstates this one's.
  Context coarse = c;
  coarse.tolerance = std::min(0.1, coarse_factor * options.tolerance);
  const Tally rough = run(ra, rb, plan, mirror, coarse, n_threads);
  out.force_error = (rough.ft.force - t.ft.force).norm();
  out.torque_error = (rough.ft.torque - t.ft.torque).norm();
  out.box_pairs = t.pairs;
  out.mirrored =
      std::any_of(plan.begin(), plan.end(), [](const RootPair& r) { return r.image_sign != 0; });
  out.kernel_evals = t.kernels;
  return out;
}

} // namespace magfem
