#pragma once
// Magnetic charge model (thesis sec. 3.4): the field of permanent magnets with mu_r = 1 from
// their surface charges sigma = M.n and volume charges rho_m = -div M,
//   H(x) = (1/4 pi) [ int sigma (x - x')/|x - x'|^3 dS' + int rho_m (x - x')/|x - x'|^3 dV' ],
// plus images in infinitely permeable spheres (sec. 3.5, see spherical_imaging.hpp). Image
// charges live only on the iron side, so fields are meaningful on the air side only.
// Radial magnets in unbounded problems are modelled by their equivalent surface currents
// (B by Biot-Savart; see ChargeModelOptions::radial_as_currents) - the same field without the
// volume integral; a test checks the two representations against each other.
// Inner permeable spheres (iron cores) also get a point charge at their centre that cancels
// the net image charge inside them (no net flux into the iron).
//
// Quadrature: every face (and volume) is a binary tree of parameter boxes with a tensor
// Gauss-Legendre rule on each; a box is used as is when the observation point is farther than
// `ratio * radius` from its centre and split along its longest direction otherwise. The ratio
// follows from the Gauss rule's convergence for an integrand with a singularity at that
// distance (Bernstein ellipse), so the relative error per box is about `tolerance`. For
// images, the test is made in the source's own space on the pre-image of the observation
// point (inversion is conformal, so near-singularity is preserved). The top levels of the
// trees are precomputed; deeper boxes (near field) are built on the fly.
//
// Evaluation is thread-safe; the vector overloads split the points over threads.
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "analytic/analytic_magnet.hpp"
#include "analytic/charge_source.hpp"
#include "analytic/spherical_imaging.hpp"

namespace magfem {

struct ChargeModelOptions {
  // Relative quadrature error per box; calibrated (default Gauss orders) so that the maximum
  // field error relative to the peak field stays below it (tested 1 mm from faces).
  double tolerance = 1e-6;
  int gauss_order = 6;        // points per direction per surface box
  int volume_gauss_order = 4; // per direction per volume box (n^3 points: lower is cheaper)
  int image_order = 2;        // longest chain of inversions (two spheres, 2 -> four images)
  int n_threads = 0;          // 0 = std::thread::hardware_concurrency()
  int cached_depth = 5;       // precomputed tree levels per root box
  double max_angle = 0.7854;  // radians: angular span of a root box (pi/4)
  // Without permeable spheres, radial magnets (curl M = 0) as surface currents M x n on their
  // cone/meridian faces instead of surface plus volume charges: same field, no volume
  // integral. With spheres, charges throughout (exact pairing of sources and images).
  bool radial_as_currents = true;
};

class ChargeModel {
public:
  // Throws std::invalid_argument for invalid shapes (see check_shape) and for magnets not
  // wholly on the air side of a permeable sphere.
  explicit ChargeModel(std::vector<AnalyticMagnet> magnets,
                       std::vector<PermeableSphere> spheres = {}, ChargeModelOptions options = {});

  // Field strength H (A/m) at global point x (metres). Inside a magnet H = B/mu0 - M.
  Eigen::Vector3d H(const Eigen::Vector3d& x) const;
  // Flux density B = mu0 (H + M) (tesla); M is the magnetization of the magnet containing x.
  Eigen::Vector3d B(const Eigen::Vector3d& x) const;
  std::vector<Eigen::Vector3d> H(const std::vector<Eigen::Vector3d>& xs) const;
  std::vector<Eigen::Vector3d> B(const std::vector<Eigen::Vector3d>& xs) const;
  // Magnetization (A/m) at x: sum over the magnets containing x.
  Eigen::Vector3d magnetization(const Eigen::Vector3d& x) const;

  const std::vector<AnalyticMagnet>& magnets() const { return magnets_; }
  const ChargeModelOptions& options() const { return options_; }
  // Number of sources (faces and volumes, originals and images).
  int n_sources() const { return static_cast<int>(sources_.size()); }

private:
  struct TreeNode {
    ParamBox box;
    Eigen::Vector3d centre; // source space
    double radius = 0;
    int axis = 0;
    int child[2] = {-1, -1}; // -1 = not precomputed
    int begin = 0, end = 0;  // range in Source::charges (image space)
  };
  struct Source {
    ChargeDomain domain;
    ImageMap map;
    std::vector<TreeNode> nodes;
    std::vector<int> roots;
    bool current = false;               // surface currents (B) instead of charges (H)
    std::vector<PointCharge> charges;   // image space
    std::vector<PointCurrent> currents; // originals only
    double min_radius = 0;              // boxes smaller than this are never split
    double ratio = 2;                   // acceptance distance / radius for its Gauss rule
  };

  void check_spheres() const;
  // Field sums at one point (divided by 4 pi), and scratch space for on-the-fly boxes.
  struct Accumulator {
    Eigen::Vector3d h_charges = Eigen::Vector3d::Zero();
    Eigen::Vector3d h_currents = Eigen::Vector3d::Zero(); // B / mu0 of current sources
    std::vector<PointCharge> charges;
    std::vector<PointCurrent> currents;
  };

  void build_source(const ChargeDomain& domain, const ImageMap& map, bool current);
  int build_node(Source& s, const ParamBox& box, int depth);
  void add_compensation();
  static void add_leaf(const Source& s, int begin, int end, const Eigen::Vector3d& x,
                       Accumulator& acc);
  void accumulate(const Source& s, int node, const Eigen::Vector3d& x, const Eigen::Vector3d& x_pre,
                  Accumulator& acc) const;
  void accumulate_box(const Source& s, const ParamBox& box, int axis, int depth,
                      const Eigen::Vector3d& x, const Eigen::Vector3d& x_pre,
                      Accumulator& acc) const;
  Accumulator evaluate(const Eigen::Vector3d& x) const;
  std::pair<Eigen::Vector3d, Eigen::Vector3d> split_magnetization(const Eigen::Vector3d& x) const;
  // By lookup, not a stored pointer, so that the model stays copyable.
  const GaussRule& rule_of(const Source& s) const;
  static bool far_enough(const Source& s, const Eigen::Vector3d& centre, double radius,
                         const Eigen::Vector3d& x_pre);
  template <class F>
  std::vector<Eigen::Vector3d> parallel_map(const std::vector<Eigen::Vector3d>& xs, F f) const;

  std::vector<AnalyticMagnet> magnets_;
  std::vector<PermeableSphere> spheres_;
  ChargeModelOptions options_;
  GaussRule surface_rule_, volume_rule_;
  std::vector<bool> as_current_; // per magnet: originals modelled by surface currents
  std::vector<Source> sources_;
  std::vector<PointCharge> point_charges_; // flux-balancing charges at inner sphere centres
};

} // namespace magfem
