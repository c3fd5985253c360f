// Charge model against exact fields: uniformly magnetized sphere (any segmentation), axial
// cylinder on its axis, divergence theorem for radial magnetization, and the thesis's
// radial-vs-parallel amplitude statement on the 32-magnet benchmark.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "analytic/benchmark32.hpp"
#include "analytic/charge_model.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

AnalyticMagnet segment(double ri, double ro, double t0, double t1, double p0, double p1, Vec3 dir,
                       double B_r) {
  AnalyticMagnet m;
  m.shape = SphericalSegment{ri, ro, t0, t1, p0, p1};
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = dir.normalized();
  m.B_r = B_r;
  return m;
}

// Exact field of a sphere of radius a with uniform remanence B_r along d centred at c:
// inside B = (2/3) B_r d; outside the field of the dipole m = (4/3) pi a^3 M.
Vec3 sphere_field(const Vec3& x, const Vec3& c, double a, const Vec3& d, double B_r) {
  const Vec3 r = x - c;
  if (r.norm() < a)
    return (2.0 / 3.0) * B_r * d;
  const Vec3 m = (4.0 / 3.0) * pi * a * a * a * (B_r / mu0) * d;
  const double rn = r.norm();
  const Vec3 rh = r / rn;
  return mu0 / (4 * pi * rn * rn * rn) * (3 * rh * rh.dot(m) - m);
}

std::vector<Vec3> probe_points(double a) {
  // Inside (away from the faces and edges of any segmentation, where the field is exact but
  // the quadrature has the hardest time only at the faces themselves) and outside, including
  // 0.1 a from the surface.
  return {Vec3(0.3, 0.2, -0.1) * a, Vec3(0.05, -0.5, 0.6) * a, Vec3(-0.7, 0.1, 0.05) * a,
          Vec3(1.1, 0.0, 0.0) * a,  Vec3(0.3, 0.9, 0.6) * a,   Vec3(-2.0, 1.0, 3.0) * a,
          Vec3(0.0, 0.0, -1.5) * a};
}

// Issue 5: 1e-6 relative (of the local exact |B|).
constexpr double sphere_tol = 1e-6;

TEST(ChargeModel, UniformSphereAsOneSegment) {
  const double a = 0.01;
  const Vec3 d = Vec3(0.3, -0.4, 0.8).normalized();
  const ChargeModel model({segment(0, a, 0, pi, 0, 2 * pi, d, 1.0)});
  for (const Vec3& x : probe_points(a)) {
    const Vec3 exact = sphere_field(x, Vec3::Zero(), a, d, 1.0);
    EXPECT_LT((model.B(x) - exact).norm(), sphere_tol * exact.norm()) << x.transpose();
  }
}

TEST(ChargeModel, UniformSphereAsFourByEightSegments) {
  const double a = 0.01;
  const Vec3 d = Vec3(0.3, -0.4, 0.8).normalized();
  std::vector<AnalyticMagnet> parts;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 8; ++j)
      parts.push_back(
          segment(0, a, i * pi / 4, (i + 1) * pi / 4, j * pi / 4, (j + 1) * pi / 4, d, 1.0));
  const ChargeModel model(parts);
  // Points off the internal faces (theta, phi multiples of 45 deg) by construction.
  const std::vector<Vec3> xs = probe_points(a);
  const std::vector<Vec3> b = model.B(xs);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const Vec3 exact = sphere_field(xs[i], Vec3::Zero(), a, d, 1.0);
    EXPECT_LT((b[i] - exact).norm(), sphere_tol * exact.norm()) << xs[i].transpose();
  }
}

TEST(ChargeModel, PlacedSphereAndSuperposition) {
  // Two hemispheres, rotated and translated, together form one sphere centred at c.
  const double a = 0.02;
  const Vec3 c(0.01, -0.02, 0.03);
  const Vec3 d = Vec3(1, 1, 0).normalized();
  AnalyticMagnet top = segment(0, a, 0, pi / 2, 0, 2 * pi, d, 1.2);
  AnalyticMagnet bottom = top;
  // Rotating the upper hemisphere by pi about x gives the lower one; direction stays global.
  bottom.placement = Placement{}.rotated(Vec3::UnitX(), pi, Vec3::Zero());
  top.placement.translation = c;
  bottom.placement.translation = c;
  const ChargeModel model({top, bottom});
  for (const Vec3& p : probe_points(a)) {
    const Vec3 x = c + p;
    const Vec3 exact = sphere_field(x, c, a, d, 1.2);
    EXPECT_LT((model.B(x) - exact).norm(), sphere_tol * exact.norm()) << p.transpose();
  }
}

TEST(ChargeModel, CopyOutlivesOriginal) {
  // Models are values (e.g. stored in containers): a copy must not refer to the original.
  const double a = 0.01;
  const Vec3 d = Vec3::UnitZ(), x(0.004, 0.003, 0.012);
  auto original = std::make_unique<ChargeModel>(
      std::vector<AnalyticMagnet>{segment(0, a, 0, pi, 0, 2 * pi, d, 1.0)});
  const Vec3 expected = original->B(x);
  const ChargeModel copy = *original;
  original.reset();
  EXPECT_EQ(copy.B(x), expected);
}

TEST(ChargeModel, AxialCylinderOnAxis) {
  // Solid cylinder radius R, height h from z = 0, magnetized along +z. On the axis the caps
  // are uniformly charged discs (+M0 at z = h, -M0 at z = 0); a disc of density s at height
  // z0 gives H_z = (s/2) [sgn(z - z0) - (z - z0)/sqrt((z - z0)^2 + R^2)], so outside
  // B_z = (B_r/2) [ (z)/sqrt(z^2 + R^2) - (z - h)/sqrt((z - h)^2 + R^2) ],
  // and inside the magnet the same expression holds for B (H + M adds the jump).
  const double R = 0.005, h = 0.012, B_r = 1.3;
  AnalyticMagnet m;
  m.shape = Cylinder{0, R, h};
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = Vec3::UnitZ();
  m.B_r = B_r;
  const ChargeModel model({m});
  for (double z : {-0.02, -0.001, 0.003, 0.006, 0.0125, 0.03}) {
    const double exact = 0.5 * B_r * (z / std::hypot(z, R) - (z - h) / std::hypot(z - h, R));
    const Vec3 b = model.B(Vec3(0, 0, z));
    EXPECT_NEAR(b.z(), exact, sphere_tol * std::abs(exact)) << z;
    EXPECT_LT(std::hypot(b.x(), b.y()), sphere_tol * std::abs(exact)) << z;
  }
}

TEST(ChargeModel, RotatedDiametricCylinderMatchesAxialRotation) {
  // A diametric cylinder is checked by symmetry: the field at a point rotated with the
  // magnet about the cylinder axis rotates with it.
  AnalyticMagnet m;
  m.shape = Cylinder{0.002, 0.006, 0.01};
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = Vec3::UnitX();
  m.B_r = 1.0;
  const Vec3 x(0.008, 0.003, 0.004);
  const Vec3 b0 = ChargeModel({m}).B(x);
  const double angle = 0.7;
  const Placement rot = Placement{}.rotated(Vec3::UnitZ(), angle, Vec3::Zero());
  AnalyticMagnet r = m;
  r.placement = rot;
  r.magnetization = m.magnetization.rotated(rot.rotation, Vec3::Zero());
  const Vec3 b1 = ChargeModel({r}).B(rot.to_global(x));
  EXPECT_LT((b1 - rot.rotation * b0).norm(), 1e-6 * b0.norm());
}

TEST(ChargeModel, RejectsInvalidShapes) {
  AnalyticMagnet m = segment(0.02, 0.01, 0, pi, 0, 2 * pi, Vec3::UnitZ(), 1.0);
  EXPECT_THROW(ChargeModel({m}), std::invalid_argument); // r_outer < r_inner
  m = segment(0, 0.01, 0, 4.0, 0, 1, Vec3::UnitZ(), 1.0);
  EXPECT_THROW(ChargeModel({m}), std::invalid_argument); // theta beyond pi
  m.shape = Cylinder{0, 0.01, 0};
  EXPECT_THROW(ChargeModel({m}), std::invalid_argument); // zero height
  m.shape = Cylinder{0, 0.01, 0.01};
  m.magnetization.direction = Vec3(0, 0, 2);
  EXPECT_THROW(ChargeModel({m}), std::invalid_argument); // not a unit vector
}

TEST(ChargeModel, RadialSegmentHasZeroNetCharge) {
  // Divergence theorem: surface charge M0 (R_out^2 - R_in^2) Omega is cancelled by the volume
  // charge -2 M0 / rho. Gauss quadrature integrates rho exactly, so round-off only.
  AnalyticMagnet m;
  m.shape = SphericalSegment{0.04, 0.055, pi / 4, pi / 2, 0.3, 1.1};
  m.magnetization.pattern = Magnetization::Pattern::radial;
  m.B_r = 1.3;
  double total = 0, magnitude = 0;
  for (const ChargeDomain& d : charge_domains(m)) {
    std::vector<PointCharge> q;
    d.quadrature(d.box, GaussRule(8), q);
    for (const PointCharge& p : q) {
      total += p.q;
      magnitude += std::abs(p.q);
    }
  }
  EXPECT_LT(std::abs(total), 1e-10 * magnitude);
  EXPECT_GT(magnitude, 0);
  // Only the two spherical faces and the volume carry charge.
  EXPECT_EQ(charge_domains(m).size(), 3u);
}

TEST(ChargeModel, RadialOffCentreShellSegmentNetCharge) {
  // Radial about a centre away from the segment's origin: cone and meridian faces now carry
  // charge too; the total is still zero.
  AnalyticMagnet m;
  m.shape = SphericalSegment{0.01, 0.02, 0.2, 1.0, 0.0, 1.5};
  m.magnetization.pattern = Magnetization::Pattern::radial;
  m.magnetization.center = Vec3(-0.03, 0.01, -0.02);
  m.B_r = 1.0;
  double total = 0, magnitude = 0;
  for (const ChargeDomain& d : charge_domains(m)) {
    // 1/|x - c| is smooth here but not polynomial: a high order is needed.
    std::vector<PointCharge> q;
    d.quadrature(d.box, GaussRule(24), q);
    for (const PointCharge& p : q) {
      total += p.q;
      magnitude += std::abs(p.q);
    }
  }
  EXPECT_LT(std::abs(total), 1e-10 * magnitude);
}

TEST(ChargeModel, RadialCurrentsEqualRadialCharges) {
  // Two independent representations of radial magnetization: surface charges on the
  // spherical faces plus the volume charge -2 M0 / rho, or surface currents M x n on the cone
  // and meridian faces (curl M = 0). Outside and inside the magnets (B includes M there) they
  // must agree to the quadrature tolerance, which checks the volume charge's sign and size.
  ChargeModelOptions charges, currents;
  charges.radial_as_currents = false;
  charges.tolerance = currents.tolerance = 1e-7;
  const auto array = make_benchmark32(Benchmark32Magnetization::radial);
  const ChargeModel a(array, {}, charges), b(array, {}, currents);
  const std::vector<Vec3> xs{Vec3(0.03, 0.02, 0.03),    Vec3(0.001, 0.002, 0.054),
                             Vec3(0.02, -0.04, 0.025),  Vec3(0.0, 0.0, 0.02),
                             Vec3(0.04, 0.013, -0.037), Vec3(0.05, 0.06, 0.01)};
  const std::vector<Vec3> ba = a.B(xs), bb = b.B(xs);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    // Inside the shell |B| ~ 1 T; 1e-6 T is the tolerance-level agreement.
    EXPECT_LT((ba[i] - bb[i]).norm(), 1e-6) << xs[i].transpose();
    EXPECT_LT((a.H(xs[i]) - b.H(xs[i])).norm(), 1e-6 / mu0) << xs[i].transpose();
  }
}

TEST(ChargeModel, UniformCuboidOnAxis) {
  // Cube-like box (half sides a, b, c) magnetized along z: on the axis the caps are charged
  // rectangles, each seen under the solid angle 4 atan(ab / (d sqrt(a^2 + b^2 + d^2))), so
  // above the box B_z = (B_r / pi) [atan(ab / ((z - c) s_-)) - atan(ab / ((z + c) s_+))].
  const double a = 0.004, b = 0.006, c = 0.003, B_r = 1.2;
  AnalyticMagnet m;
  m.shape = Box{Vec3(2 * a, 2 * b, 2 * c)};
  m.magnetization.pattern = Magnetization::Pattern::parallel;
  m.magnetization.direction = Vec3::UnitZ();
  m.B_r = B_r;
  const ChargeModel model({m});
  for (double z : {0.0035, 0.005, 0.02}) {
    auto term = [&](double d) { return std::atan(a * b / (d * std::sqrt(a * a + b * b + d * d))); };
    const double exact = B_r / pi * (term(z - c) - term(z + c));
    const Vec3 field = model.B(Vec3(0, 0, z));
    EXPECT_NEAR(field.z(), exact, sphere_tol * std::abs(exact)) << z;
    EXPECT_LT(std::hypot(field.x(), field.y()), sphere_tol * std::abs(exact)) << z;
  }
}

TEST(ChargeModel, ToleranceBoundsTheErrorNearFaces) {
  // The exposed tolerance is calibrated so that the maximum error relative to the peak field
  // stays below it, including 1 mm from the 55 mm faces (r56 points, parallel and radial).
  std::vector<Vec3> xs;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double t = (3 + 11.3 * i) * deg_to_rad, p = (1 + 11.7 * j) * deg_to_rad;
      xs.push_back(0.056 * Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)));
    }
  for (auto kind : {Benchmark32Magnetization::parallel_centred, Benchmark32Magnetization::radial}) {
    ChargeModelOptions loose, tight;
    loose.tolerance = 1e-3;
    tight.tolerance = 1e-8;
    const std::vector<Vec3> b = ChargeModel(make_benchmark32(kind), {}, loose).B(xs);
    const std::vector<Vec3> ref = ChargeModel(make_benchmark32(kind), {}, tight).B(xs);
    double err = 0, peak = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      err = std::max(err, (b[i] - ref[i]).norm());
      peak = std::max(peak, ref[i].norm());
    }
    EXPECT_LT(err, loose.tolerance * peak) << to_string(kind);
    EXPECT_GT(err, 0); // the loose model does differ: the comparison is not vacuous
  }
}

// Peak of |B_rho| on the r56 observation grid (theta, phi in 0..90 deg, 2 deg steps; the
// amplitude statement concerns the envelope, and 2 deg resolves it to well below 1 %).
double peak_b_rho(const ChargeModel& model) {
  std::vector<Vec3> xs;
  for (int i = 0; i <= 45; ++i)
    for (int j = 0; j <= 45; ++j) {
      const double t = i * 2 * deg_to_rad, p = j * 2 * deg_to_rad;
      xs.push_back(Benchmark32::r_observation *
                   Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)));
    }
  const std::vector<Vec3> b = model.B(xs);
  double peak = 0;
  for (std::size_t i = 0; i < xs.size(); ++i)
    peak = std::max(peak, std::abs(b[i].dot(xs[i].normalized())));
  return peak;
}

TEST(ChargeModel, Benchmark32RadialAmplitudeBelowParallel) {
  // paper_targets A / thesis sec. 3.8.2: radial B_rho amplitude about 20 % below the
  // parallel one (centred convention), within 3 points.
  ChargeModelOptions opt;
  opt.tolerance = 1e-4; // amplitude ratio to 0.1 % is ample for a 3-point criterion
  const double parallel = peak_b_rho(
      ChargeModel(make_benchmark32(Benchmark32Magnetization::parallel_centred), {}, opt));
  const double radial =
      peak_b_rho(ChargeModel(make_benchmark32(Benchmark32Magnetization::radial), {}, opt));
  const double reduction = 1 - radial / parallel;
  RecordProperty("parallel_peak_T", std::to_string(parallel));
  RecordProperty("radial_peak_T", std::to_string(radial));
  EXPECT_NEAR(reduction, 0.20, 0.03) << "parallel " << parallel << " T, radial " << radial << " T";
  // The literal eq. 3.113 (direction at the segment edge) gives a stronger parallel array and
  // about 30 % (paper_targets A): the reason the centred reading is the convention.
  const double edge =
      peak_b_rho(ChargeModel(make_benchmark32(Benchmark32Magnetization::parallel_edge), {}, opt));
  RecordProperty("parallel_edge_peak_T", std::to_string(edge));
  EXPECT_NEAR(1 - radial / edge, 0.30, 0.03) << "edge " << edge << " T";
}

} // namespace
} // namespace magfem
