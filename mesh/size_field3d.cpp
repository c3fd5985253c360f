#include "mesh/size_field3d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace magfem {
namespace {
constexpr int leaf_size = 8;
// Relative pruning slack of the branch-and-bound: subtrees that could lower the minimum by
// less than this fraction are skipped, so the result is at most 1 / (1 - slack) above the
// exact field (where sources tie, far from them); near a dominant source it is exact. Far from
// the sources (where nearly all subtrees tie) this turns a scan into a short search.
constexpr double prune_slack = size_field_slack;
} // namespace

void SizeField3D::add_source(const Vec3& x, double h) {
  src_x_.push_back(x);
  src_h_.push_back(h);
}

void SizeField3D::add_probe(const ProbeSurface& probe, double h) {
  probes_.push_back({probe, h});
  h_min_ = std::min(h_min_, h);
}

void SizeField3D::build() {
  // Sort sources into kd order in place (the tree refers to contiguous ranges).
  std::vector<int> order(src_x_.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<Vec3> x(src_x_);
  std::vector<double> h(src_h_);
  nodes_.clear();
  if (src_x_.empty())
    return;
  // Partition indices recursively, then permute the arrays.
  struct Range {
    int begin, end;
  };
  std::vector<Range> stack{{0, static_cast<int>(order.size())}};
  while (!stack.empty()) {
    const Range r = stack.back();
    stack.pop_back();
    if (r.end - r.begin <= leaf_size)
      continue;
    Eigen::AlignedBox3d box;
    for (int i = r.begin; i < r.end; ++i)
      box.extend(x[order[i]]);
    int axis = 0;
    box.sizes().maxCoeff(&axis);
    const int mid = (r.begin + r.end) / 2;
    std::nth_element(order.begin() + r.begin, order.begin() + mid, order.begin() + r.end,
                     [&](int a, int b) { return x[a][axis] < x[b][axis]; });
    stack.push_back({r.begin, mid});
    stack.push_back({mid, r.end});
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    src_x_[i] = x[order[i]];
    src_h_[i] = h[order[i]];
  }
  build_node(0, static_cast<int>(src_x_.size()));
  h_min_ = std::min(h_min_, nodes_[0].h_min);
}

// The same median split as in build(), so every node covers a contiguous range.
int SizeField3D::build_node(int begin, int end) {
  const int id = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Node n;
  n.begin = begin;
  n.end = end;
  n.h_min = std::numeric_limits<double>::infinity();
  for (int i = begin; i < end; ++i) {
    n.box.extend(src_x_[i]);
    n.h_min = std::min(n.h_min, src_h_[i]);
  }
  if (end - begin > leaf_size) {
    const int mid = (begin + end) / 2;
    n.child[0] = build_node(begin, mid);
    n.child[1] = build_node(mid, end);
  }
  nodes_[id] = n;
  return id;
}

double SizeField3D::probe_size(const Probe& p, const Vec3& x) const {
  const ProbeSurface& s = p.surface;
  const Vec3 v = x - s.center;
  const double r = v.norm();
  double d = s.radius;
  if (r > 0) {
    // Nearest point of the patch, approximated by clamping the direction's angles.
    double theta = std::acos(std::clamp(v.z() / r, -1.0, 1.0));
    theta = std::clamp(theta, s.theta_min, s.theta_max);
    double phi = std::atan2(v.y(), v.x());
    const double mid = 0.5 * (s.phi_min + s.phi_max), half = 0.5 * (s.phi_max - s.phi_min);
    phi = mid + std::clamp(std::remainder(phi - mid, 2 * std::numbers::pi), -half, half);
    const Vec3 q = s.center + s.radius * Vec3(std::sin(theta) * std::cos(phi),
                                              std::sin(theta) * std::sin(phi), std::cos(theta));
    d = (x - q).norm();
  }
  return p.h + grading_ * std::max(0.0, d - p.h);
}

double SizeField3D::operator()(const Vec3& x) const {
  double best = h_max_;
  for (const Probe& p : probes_)
    best = std::min(best, probe_size(p, x));
  if (nodes_.empty())
    return best;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (n.h_min + grading_ * std::sqrt(n.box.squaredExteriorDistance(x)) >=
        (1 - prune_slack) * best)
      continue;
    if (n.child[0] < 0) {
      for (int i = n.begin; i < n.end; ++i)
        best = std::min(best, src_h_[i] + grading_ * (src_x_[i] - x).norm());
      continue;
    }
    // Visit the nearer child first (pushed last).
    const double d0 = nodes_[n.child[0]].box.squaredExteriorDistance(x);
    const double d1 = nodes_[n.child[1]].box.squaredExteriorDistance(x);
    stack[top++] = d0 < d1 ? n.child[1] : n.child[0];
    stack[top++] = d0 < d1 ? n.child[0] : n.child[1];
  }
  return best;
}

} // namespace magfem
