#pragma once
// Graded mesh-size field h(x) = min( min_i (h_i + g |x - x_i|), min_p h_p(x) ) over point
// sources (x_i, h_i) and probe surfaces p, where g is the grading (metres of size per metre of
// distance). A kd-tree with a branch-and-bound on h_i + g * distance makes each evaluation
// about logarithmic in the number of sources; the bound prunes with a relative slack
// (size_field_slack), so a value may exceed the exact field by up to that fraction.
inline constexpr double size_field_slack = 0.05;
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/geometry3d.hpp"
#include "mesh/mesh3d.hpp"

namespace magfem {

class SizeField3D {
public:
  explicit SizeField3D(double grading, double h_max = std::numeric_limits<double>::infinity())
      : grading_(grading), h_max_(h_max) {}

  void add_source(const Vec3& x, double h);
  // Size h within a band of half-width h about the probe patch, graded beyond.
  void add_probe(const ProbeSurface& probe, double h);
  void build(); // call after the last add_*, before evaluating

  double operator()(const Vec3& x) const;
  double min_size() const { return h_min_; }
  double grading() const { return grading_; }
  std::size_t n_sources() const { return src_x_.size(); }

private:
  struct Node {
    Eigen::AlignedBox3d box;
    double h_min = 0;
    int begin = 0, end = 0; // source range (leaves)
    int child[2] = {-1, -1};
  };
  struct Probe {
    ProbeSurface surface;
    double h = 0;
  };
  int build_node(int begin, int end);
  double probe_size(const Probe& p, const Vec3& x) const;

  double grading_;
  double h_max_;
  double h_min_ = std::numeric_limits<double>::infinity();
  std::vector<Vec3> src_x_;
  std::vector<double> src_h_;
  std::vector<Probe> probes_;
  std::vector<Node> nodes_;
};

} // namespace magfem
