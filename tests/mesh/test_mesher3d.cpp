// Tests of the 3D mesher: exact volumes of every primitive, conformity of segment arrays,
// element validity and quality, the open-boundary shell, rejection of bad geometry, gap layers
// and probe refinement. Meshes are coarse to keep the suite fast.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <map>
#include <thread>

#include <Eigen/Geometry>
#include <numbers>

#include "mesh/mesh_error.hpp"
#include "mesh/mesh_quality3d.hpp"
#include "mesh/mesher3d.hpp"
#include "tests/mesh/segment_part3d.hpp"

namespace magfem {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double mm = 1e-3;

using test::segment;

double segment_volume(double r1, double r2, double t1, double t2, double p1, double p2) {
  return (std::pow(r2, 3) - std::pow(r1, 3)) / 3 * (std::cos(t1) - std::cos(t2)) * (p2 - p1);
}

Geometry3D domain(double radius, double default_size, double chord_tol) {
  Geometry3D g;
  g.outer.kind = OuterKind3D::open;
  g.outer.radius = radius;
  g.outer.shell_ratio = 1.5;
  g.options.default_size = default_size;
  g.options.chord_tolerance = chord_tol;
  return g;
}

// Every face of every tet is either shared by exactly two tets or lies on the outer boundary.
// Returns the number of faces between tets of different labels.
// Calls on_interface(face, part_a, part_b) for faces between two tets of different labels.
template <class OnInterface> void check_conforming(const Mesh3D& m, OnInterface on_interface) {
  struct Face {
    std::array<int, 3> v;
    int tet;
  };
  std::vector<Face> faces;
  faces.reserve(4 * m.tets.size());
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> key{m.tets[t][(f + 1) % 4], m.tets[t][(f + 2) % 4],
                             m.tets[t][(f + 3) % 4]};
      std::sort(key.begin(), key.end());
      faces.push_back({key, static_cast<int>(t)});
    }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.v < b.v; });
  std::vector<std::array<int, 3>> outer;
  for (auto f : m.outer_faces) {
    std::sort(f.begin(), f.end());
    outer.push_back(f);
  }
  std::sort(outer.begin(), outer.end());
  std::size_t boundary = 0, non_manifold = 0, stray = 0;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].v == faces[i].v)
      ++j;
    if (j - i > 2)
      ++non_manifold;
    if (j - i == 1) {
      ++boundary;
      stray += !std::binary_search(outer.begin(), outer.end(), faces[i].v);
    } else if (m.tet_part[faces[i].tet] != m.tet_part[faces[i + 1].tet]) {
      on_interface(faces[i].v, m.tet_part[faces[i].tet], m.tet_part[faces[i + 1].tet]);
    }
    i = j;
  }
  EXPECT_EQ(non_manifold, 0u) << "faces shared by more than two tets";
  EXPECT_EQ(stray, 0u) << "boundary faces not on the outer sphere (gaps in the mesh)";
  EXPECT_EQ(boundary, m.outer_faces.size());
}

void check_conforming(const Mesh3D& m) {
  check_conforming(m, [](const std::array<int, 3>&, int, int) {});
}

// Volumes and angles recomputed here from the coordinates, independently of the mesher's
// own report (mesh/mesh_quality3d), which is then checked against them.
double signed_volume(const Mesh3D& m, const std::array<int, 4>& t) {
  const Vec3 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]], &d = m.nodes[t[3]];
  return (b - a).dot((c - a).cross(d - a)) / 6;
}

double part_volume(const Mesh3D& m, int part) {
  double v = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t)
    if (m.tet_part[t] == part)
      v += std::abs(signed_volume(m, m.tets[t]));
  return v;
}

// Dihedral angle at edge (i, j) between the faces (i, j, k) and (i, j, l).
double dihedral_deg(const Vec3& pi_, const Vec3& pj, const Vec3& pk, const Vec3& pl) {
  const Vec3 e = (pj - pi_).normalized();
  Vec3 u = pk - pi_, w = pl - pi_;
  u -= u.dot(e) * e;
  w -= w.dot(e) * e;
  return std::acos(std::clamp(u.normalized().dot(w.normalized()), -1.0, 1.0)) * 180 / pi;
}

std::pair<double, double> dihedral_range(const Mesh3D& m) {
  constexpr int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                               {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double lo = 180, hi = 0;
  for (const auto& t : m.tets)
    for (const auto& e : edges) {
      const double a =
          dihedral_deg(m.nodes[t[e[0]]], m.nodes[t[e[1]]], m.nodes[t[e[2]]], m.nodes[t[e[3]]]);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
  return {lo, hi};
}

void check_elements(const Mesh3D& m, double min_dihedral_bound_deg) {
  ASSERT_EQ(m.tets.size(), m.tet_part.size());
  double min_vol = std::numeric_limits<double>::infinity();
  for (const auto& t : m.tets)
    min_vol = std::min(min_vol, std::abs(signed_volume(m, t)));
  EXPECT_GT(min_vol, 0);
  const auto [lo, hi] = dihedral_range(m);
  EXPECT_GT(lo, min_dihedral_bound_deg);
  EXPECT_LT(hi, 180 - min_dihedral_bound_deg);
  // The mesher's report says the same.
  EXPECT_NEAR(m.quality.min_dihedral_deg, lo, 1e-6);
  EXPECT_NEAR(m.quality.max_dihedral_deg, hi, 1e-6);
  for (std::size_t p = 0; p < m.part_volumes.size(); ++p)
    EXPECT_NEAR(m.part_volumes[p], part_volume(m, static_cast<int>(p)), 1e-12 * m.part_volumes[p]);
}

TEST(Mesher3D, SolidSphereVolumeShellAndOuterFaces) {
  Geometry3D g = domain(30 * mm, 8 * mm, 0.02 * mm);
  g.parts.push_back(segment("ball", 0, 10 * mm, 0, pi, 0, 2 * pi));
  g.parts[0].max_size = 3 * mm;
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh3D m = build_mesh_3d(g);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("sphere: %zu nodes %zu tets in %.2f s, dihedral %.1f..%.1f, radius-edge %.2f\n",
              m.nodes.size(), m.tets.size(), secs, m.quality.min_dihedral_deg,
              m.quality.max_dihedral_deg, m.quality.max_radius_edge);
  const double exact = 4.0 / 3 * pi * std::pow(10 * mm, 3);
  // Inscribed facets lose at most sagitta * area / V = 3 * 0.02 mm / 10 mm = 0.6 %, on average
  // about half that; 0.5 % is the volume requirement.
  EXPECT_NEAR(part_volume(m, 0), exact, 0.005 * exact);
  check_elements(m, 5.0);
  check_conforming(m);
  EXPECT_DOUBLE_EQ(m.shell_inner_radius, 30 * mm);
  EXPECT_DOUBLE_EQ(m.shell_outer_radius, 45 * mm);
  EXPECT_GT(std::count(m.tet_part.begin(), m.tet_part.end(), region_shell_3d), 0);
  for (const auto& f : m.outer_faces)
    for (int v : f)
      EXPECT_NEAR(m.nodes[v].norm(), 45 * mm, 1e-12);
}

// mesh.shell_size coarsens the open-boundary shell alone: the shell (which maps the exterior
// and carries a smooth, decaying field) gets fewer elements, the ball inside it keeps its mesh,
// the shell's volume and outer faces stay exact. The shell's tet count must fall by more
// than a quarter for a doubled size (measured: 38 %; the grading from the inner sphere's 6 mm
// facets limits it; a cap that is not applied leaves the count unchanged); the ball's may
// move by the interface triangulation only (10 %; measured 0.3 %).
TEST(Mesher3D, ShellSizeCoarsensTheShellAndKeepsTheBall) {
  auto build = [](double shell_size) {
    Geometry3D g = domain(30 * mm, 6 * mm, 0.02 * mm);
    g.parts.push_back(segment("ball", 0, 10 * mm, 0, pi, 0, 2 * pi));
    g.parts[0].max_size = 3 * mm;
    g.options.shell_size = shell_size;
    return build_mesh_3d(g);
  };
  auto count = [](const Mesh3D& m, bool shell) {
    return std::count_if(m.tet_part.begin(), m.tet_part.end(),
                         [&](int p) { return (p == region_shell_3d) == shell; });
  };
  const Mesh3D same = build(0), coarse = build(12 * mm);
  std::printf("shell tets %td -> %td, ball and air %td -> %td\n", count(same, true),
              count(coarse, true), count(same, false), count(coarse, false));
  EXPECT_LT(count(coarse, true), 3 * count(same, true) / 4);
  EXPECT_NEAR(static_cast<double>(count(coarse, false)), static_cast<double>(count(same, false)),
              0.1 * static_cast<double>(count(same, false)));
  double shell_volume = 0;
  for (std::size_t t = 0; t < coarse.tets.size(); ++t)
    if (coarse.tet_part[t] == region_shell_3d) {
      const auto& v = coarse.tets[t];
      shell_volume += (coarse.nodes[v[1]] - coarse.nodes[v[0]])
                          .cross(coarse.nodes[v[2]] - coarse.nodes[v[0]])
                          .dot(coarse.nodes[v[3]] - coarse.nodes[v[0]]) /
                      6;
    }
  // Inscribed facets of the outer sphere lose about half their sagitta (h^2 / 8R = 0.4 mm for
  // 12 mm facets on 45 mm) times its area, 1.9 % of the shell's volume (the inner sphere's
  // 6 mm facets give a little back): 2 %. Measured -1.37 %.
  const double exact = 4.0 / 3 * pi * (std::pow(45 * mm, 3) - std::pow(30 * mm, 3));
  std::printf("shell volume %+.3f %%\n", 100 * (shell_volume / exact - 1));
  EXPECT_NEAR(shell_volume, exact, 0.02 * exact);
  check_conforming(coarse);
  for (const auto& f : coarse.outer_faces)
    for (int v : f)
      EXPECT_NEAR(coarse.nodes[v].norm(), 45 * mm, 1e-12);
}

// Largest edge of a tet.
double longest_edge(const Mesh3D& m, const std::array<int, 4>& t) {
  double l = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      l = std::max(l, (m.nodes[t[i]] - m.nodes[t[j]]).norm());
  return l;
}

Eigen::Vector3d centroid(const Mesh3D& m, const std::array<int, 4>& t) {
  return (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]] + m.nodes[t[3]]) / 4;
}

// The thesis benchmark: full shell 40..55 mm cut into 4 x 8 segments of 45 x 45 deg.
Geometry3D benchmark32(double magnet_size, double default_size, double chord_tol) {
  Geometry3D g = domain(100 * mm, default_size, chord_tol);
  const double q = pi / 4;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 8; ++j) {
      char name[16];
      std::snprintf(name, sizeof name, "m%d_%d", i + 1, j + 1);
      g.parts.push_back(segment(name, 40 * mm, 55 * mm, i * q, (i + 1) * q, j * q, (j + 1) * q));
      g.parts.back().max_size = magnet_size;
    }
  return g;
}

TEST(Mesher3D, SegmentArrayConformsAndKeepsVolumes) {
  const Geometry3D g = benchmark32(6 * mm, 25 * mm, 0.1 * mm);
  const Mesh3D m = build_mesh_3d(g);
  std::printf("benchmark32 coarse: %zu tets, dihedral %.1f..%.1f, radius-edge %.2f\n",
              m.tets.size(), m.quality.min_dihedral_deg, m.quality.max_dihedral_deg,
              m.quality.max_radius_edge);
  check_elements(m, 5.0);
  // Interfaces between two magnets must lie on a cut: a plane phi = k 45 deg, the cone
  // theta = 45 / 135 deg or the plane theta = 90 deg.
  std::size_t between_parts = 0, off_cut = 0;
  check_conforming(m, [&](const std::array<int, 3>& f, int a, int b) {
    if (a < 0 || b < 0)
      return;
    ++between_parts;
    for (int v : f) {
      const Eigen::Vector3d x = m.nodes[v];
      const double theta = std::acos(x.z() / x.norm());
      const double phi = std::atan2(x.y(), x.x());
      const double dphi = std::abs(std::remainder(phi, pi / 4)) * x.head<2>().norm();
      const double dtheta = std::abs(std::remainder(theta, pi / 4)) * x.norm();
      off_cut += std::min(dphi, dtheta) > 1e-9;
    }
  });
  EXPECT_GT(between_parts, 0u);
  EXPECT_EQ(off_cut, 0u);
  double total = 0;
  for (std::size_t p = 0; p < g.parts.size(); ++p) {
    const auto& s = std::get<SphericalSegment>(g.parts[p].shape);
    const double exact =
        segment_volume(s.r_inner, s.r_outer, s.theta_min, s.theta_max, s.phi_min, s.phi_max);
    // Chord tolerance 0.1 mm: net facet error (outer loss minus inner gain) ~0.2 %.
    EXPECT_NEAR(part_volume(m, p), exact, 0.005 * exact) << g.parts[p].name;
    total += part_volume(m, p);
  }
  const double shell = 4 * pi / 3 * (std::pow(55 * mm, 3) - std::pow(40 * mm, 3));
  EXPECT_NEAR(total, shell, 0.005 * shell);
  for (int p = 0; p < 32; ++p)
    EXPECT_GT(std::count(m.tet_part.begin(), m.tet_part.end(), p), 0);
}

// Scaled gravity compensator (R 29 mm in a 30..43 mm shell): solid hemisphere R 3 mm inside a
// hemispherical shell 4..6 mm, flat faces in the xy-plane, the same 1 mm air gap.
TEST(Mesher3D, HemispheresWithGapLayers) {
  // Chord 0.01 mm: the facets of the 6 mm face lose about (mean sagitta ~0.004 mm) * area /
  // volume = 0.3 % of the thin outer shell.
  Geometry3D g = domain(20 * mm, 6 * mm, 0.01 * mm);
  g.options.gap_layers = 3;
  g.parts.push_back(segment("inner", 0, 3 * mm, 0, pi / 2, 0, 2 * pi));
  g.parts.push_back(segment("outer", 4 * mm, 6 * mm, 0, pi / 2, 0, 2 * pi));
  const Mesh3D m = build_mesh_3d(g);
  std::printf("hemispheres: %zu tets, dihedral %.1f..%.1f\n", m.tets.size(),
              m.quality.min_dihedral_deg, m.quality.max_dihedral_deg);
  check_elements(m, 5.0);
  check_conforming(m);
  const double v_in = 2 * pi / 3 * std::pow(3 * mm, 3);
  const double v_out = 2 * pi / 3 * (std::pow(6 * mm, 3) - std::pow(4 * mm, 3));
  EXPECT_NEAR(part_volume(m, 0), v_in, 0.005 * v_in);
  EXPECT_NEAR(part_volume(m, 1), v_out, 0.005 * v_out);
  // Air tets inside the gap (away from the rim at z = 0): at least 3 layers, i.e. no edge
  // longer than gap / 3.
  double worst = 0;
  std::size_t n_gap = 0;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    if (m.tet_part[t] != region_background_3d)
      continue;
    const Eigen::Vector3d c = centroid(m, m.tets[t]);
    if (c.norm() < 3 * mm || c.norm() > 4 * mm || c.z() < 1 * mm)
      continue;
    ++n_gap;
    worst = std::max(worst, longest_edge(m, m.tets[t]));
  }
  EXPECT_GT(n_gap, 100u);
  EXPECT_LE(worst, (1 * mm) / 3 * (1 + 1e-9));
}

// A gap lies between two parts, not between a part and the domain boundary: a sphere 5 mm
// inside the ball (3 layers across would ask for 1.7 mm elements in air meshed at 8 mm) meshes
// the same with gap_layers 1 and 3; before this rule the outer boundary counted as the far
// side of a gap and refined the whole air ball (benchmark32 at size 20: 524k tets instead of
// 45k). A second sphere 1 mm from the first still gets its gap refined.
TEST(Mesher3D, SpaceBetweenAPartAndTheBoundaryIsNoGap) {
  auto tets = [](int layers, bool second) {
    Geometry3D g = domain(20 * mm, 8 * mm, 0.1 * mm);
    g.options.gap_layers = layers;
    g.parts.push_back(segment("ball", 0, 15 * mm, 0, pi, 0, 2 * pi));
    if (second) {
      g.parts[0] = segment("ball", 0, 6 * mm, 0, pi, 0, 2 * pi);
      Part3D p = segment("other", 0, 5 * mm, 0, pi, 0, 2 * pi);
      p.placement.translation = Eigen::Vector3d(12 * mm, 0, 0); // 1 mm from "ball"
      g.parts.push_back(p);
    }
    return build_mesh_3d(g).tets.size();
  };
  const std::size_t alone1 = tets(1, false), alone3 = tets(3, false);
  const std::size_t pair1 = tets(1, true), pair3 = tets(3, true);
  std::printf("sphere alone: %zu / %zu tets (gap_layers 1 / 3); pair 1 mm apart: %zu / %zu\n",
              alone1, alone3, pair1, pair3);
  EXPECT_EQ(alone1, alone3);
  EXPECT_GT(pair3, pair1 * 3 / 2);
}

// Cylinders of any placement, hollow and solid, a ring of them pointing radially on a sphere
// (as the thesis's outer magnet of 178 cylinders) and a rotated box.
TEST(Mesher3D, CylindersOnSphereAndBoxVolumes) {
  Geometry3D g = domain(60 * mm, 15 * mm, 0.02 * mm);
  const int n = 4;
  for (int k = 0; k < n; ++k) {
    const double theta = pi / 2 + 0.3 * std::sin(k);
    const double phi = 2 * pi * k / n;
    const Eigen::Vector3d dir(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
    Part3D c;
    c.name = "cyl" + std::to_string(k);
    c.shape = Cylinder{k % 2 ? 3 * mm : 0.0, 6 * mm, 6 * mm};
    c.placement.rotation =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), dir).toRotationMatrix();
    c.placement.translation = 35 * mm * dir;
    g.parts.push_back(c);
  }
  Part3D b;
  b.name = "box";
  b.shape = Box{Eigen::Vector3d(6 * mm, 4 * mm, 3 * mm)};
  b.placement = b.placement.rotated(Eigen::Vector3d(1, 2, 3), 0.7, Eigen::Vector3d::Zero());
  g.parts.push_back(b);
  const Mesh3D m = build_mesh_3d(g);
  std::printf("cylinders+box: %zu tets, dihedral %.1f..%.1f\n", m.tets.size(),
              m.quality.min_dihedral_deg, m.quality.max_dihedral_deg);
  check_elements(m, 5.0);
  check_conforming(m);
  for (int k = 0; k < n; ++k) {
    const auto& c = std::get<Cylinder>(g.parts[k].shape);
    const double exact = pi * (c.r_outer * c.r_outer - c.r_inner * c.r_inner) * c.height;
    // Facets on the 3 and 6 mm radii lose 2 * (mean sagitta) / r, with sagitta <= 0.02 mm
    // about 0.3 %.
    EXPECT_NEAR(part_volume(m, k), exact, 0.005 * exact) << g.parts[k].name;
  }
  const double v_box = 6 * 4 * 3 * std::pow(mm, 3);
  EXPECT_NEAR(part_volume(m, n), v_box, 1e-9 * v_box);
}

TEST(Mesher3D, RejectsIntersectingPartsNamingBoth) {
  Geometry3D g = domain(100 * mm, 20 * mm, 0.5 * mm);
  g.parts.push_back(segment("shell_a", 40 * mm, 55 * mm, 0, pi / 2, 0, pi / 2));
  g.parts.push_back(segment("shell_b", 50 * mm, 60 * mm, pi / 4, pi / 2, 0, pi / 4));
  try {
    build_mesh_3d(g);
    FAIL() << "overlapping segments accepted";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("shell_a"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("shell_b"), std::string::npos) << e.what();
  }
  // Different frames: a box cutting through a segment.
  g.parts.pop_back();
  Part3D b;
  b.name = "brick";
  b.shape = Box{Eigen::Vector3d(10 * mm, 10 * mm, 10 * mm)};
  b.placement.translation = Eigen::Vector3d(30 * mm, 30 * mm, 30 * mm);
  g.parts.push_back(b);
  try {
    build_mesh_3d(g);
    FAIL() << "box through a segment accepted";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("shell_a"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("brick"), std::string::npos) << e.what();
  }
  // A part entirely inside another part of a different frame.
  g.parts.back().shape = Box{Eigen::Vector3d(2 * mm, 2 * mm, 2 * mm)};
  g.parts.back().placement.translation = Eigen::Vector3d(25 * mm, 25 * mm, 25 * mm);
  EXPECT_THROW(build_mesh_3d(g), MeshError);
}

TEST(Mesher3D, RejectsDegenerateAndOutsideParts) {
  auto error_of = [](const Geometry3D& g) {
    try {
      build_mesh_3d(g);
    } catch (const MeshError& e) {
      return e.part + "/" + e.field;
    }
    return std::string("accepted");
  };
  Geometry3D g = domain(100 * mm, 20 * mm, 0.5 * mm);
  g.parts.push_back(segment("flat", 40 * mm, 40 * mm, 0, pi / 2, 0, pi / 2));
  EXPECT_EQ(error_of(g), "flat/r_outer");
  g.parts[0] = segment("thin", 40 * mm, 50 * mm, pi / 2, pi / 2, 0, pi / 2);
  EXPECT_EQ(error_of(g), "thin/theta_max");
  g.parts[0] = segment("wide", 40 * mm, 50 * mm, 0, pi / 2, 0, 3 * pi);
  EXPECT_EQ(error_of(g), "wide/phi_max");
  g.parts[0].name = "can";
  g.parts[0].shape = Cylinder{0, 5 * mm, 0};
  EXPECT_EQ(error_of(g), "can/height");
  g.parts[0].name = "brick";
  g.parts[0].shape = Box{Eigen::Vector3d(1 * mm, 0, 1 * mm)};
  EXPECT_EQ(error_of(g), "brick/size");
  g.parts[0] = segment("big", 40 * mm, 120 * mm, 0, pi / 2, 0, pi / 2);
  EXPECT_EQ(error_of(g), "big/");
  // Shells thinner than 1.5 facet sagittas: before this check TetGen found the faceted
  // surfaces crossing and the process aborted inside the library (10 um at chord 50 um).
  g.options.chord_tolerance = 0.05 * mm;
  g.parts[0] = segment("foil", 10 * mm, 10.01 * mm, 0, pi, 0, 2 * pi);
  EXPECT_EQ(error_of(g), "foil/r_inner");
  g.parts[0].name = "tube";
  g.parts[0].shape = Cylinder{5 * mm, 5.001 * mm, 10 * mm};
  EXPECT_EQ(error_of(g), "tube/r_inner");
  // Without a chord tolerance the facets follow the mesh size: 20 mm facets on the 15 mm
  // outer sphere may be 4.4 mm deep, so even a 5 mm shell is refused.
  g.options.chord_tolerance = 0;
  g.parts[0] = segment("coarse", 10 * mm, 15 * mm, 0, pi, 0, 2 * pi);
  EXPECT_EQ(error_of(g), "coarse/r_inner");
  g.options.chord_tolerance = 0.5 * mm;
  g.parts[0].name = "far";
  g.parts[0].shape = Box{Eigen::Vector3d(10 * mm, 10 * mm, 10 * mm)};
  g.parts[0].placement.translation = Eigen::Vector3d(97 * mm, 0, 0);
  EXPECT_EQ(error_of(g), "far/");
}

TEST(Mesher3D, ProbeSphereRefinement) {
  Geometry3D g = domain(30 * mm, 8 * mm, 0.05 * mm);
  g.options.probe_size = 0.8 * mm;
  g.parts.push_back(segment("ball", 0, 10 * mm, 0, pi, 0, 2 * pi));
  g.parts[0].max_size = 3 * mm;
  ProbeSurface probe;
  probe.radius = 12 * mm;
  probe.theta_min = 0;
  probe.theta_max = pi / 2;
  probe.phi_min = 0;
  probe.phi_max = pi / 2;
  const Mesh3D m = build_mesh_3d(g, {probe});
  std::printf("probe: %zu tets\n", m.tets.size());
  check_elements(m, 5.0);
  double worst = 0;
  std::size_t n_band = 0;
  for (const auto& t : m.tets) {
    const Eigen::Vector3d c = centroid(m, t);
    if (std::abs(c.norm() - 12 * mm) > 0.4 * mm || c.minCoeff() < 0.5 * mm)
      continue;
    ++n_band;
    worst = std::max(worst, longest_edge(m, t));
  }
  EXPECT_GT(n_band, 1000u);
  EXPECT_LE(worst, 0.8 * mm * (1 + 1e-9));
}

// Timing figures of the long-tier tests below.
void print_figures(const char* what, const Mesh3D& m, double wall, double cpu) {
  std::printf("%s: %zu nodes, %zu tets, %.2f s wall, %.2f s cpu, %.0f tets/cpu-s, dihedral "
              "%.1f..%.1f, radius-edge %.2f\n",
              what, m.nodes.size(), m.tets.size(), wall, cpu, m.tets.size() / cpu,
              m.quality.min_dihedral_deg, m.quality.max_dihedral_deg, m.quality.max_radius_edge);
  const auto air = std::count(m.tet_part.begin(), m.tet_part.end(), region_background_3d);
  const auto shell = std::count(m.tet_part.begin(), m.tet_part.end(), region_shell_3d);
  std::printf("  tets in parts %zu, air %zu, shell %zu\n",
              m.tets.size() - static_cast<std::size_t>(air + shell), static_cast<std::size_t>(air),
              static_cast<std::size_t>(shell));
}

// Figures for the report (long tier: bash scripts/test.sh --long): the 32-magnet benchmark
// with the observation patch r = 56 mm, theta, phi in [0, 90] deg, at a few resolutions.
TEST(Mesher3D, LongBenchmark32Timing) {
  struct Level {
    double chord, magnet_size, scale;
  };
  for (const Level& level : {Level{0.05 * mm, 4 * mm, 1.5}, Level{0.05 * mm, 4 * mm, 1.0},
                             Level{0.02 * mm, 4 * mm, 1.0}, Level{0.02 * mm, 3 * mm, 0.8}}) {
    Geometry3D g = benchmark32(level.magnet_size, 12 * mm, level.chord);
    g.options.probe_size = 1 * mm;
    g.options.size_scale = level.scale;
    ProbeSurface probe;
    probe.radius = 56 * mm;
    probe.theta_max = pi / 2;
    probe.phi_max = pi / 2;
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const Mesh3D m = build_mesh_3d(g, {probe});
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("benchmark32 chord %.3f mm, magnets %.0f mm, probe 1 mm, scale %.2f:\n",
                level.chord / mm, level.magnet_size / mm, level.scale);
    print_figures("  ", m, s, cpu);
    // At this size the mesher must keep its promises too: positive volumes, dihedral angles
    // inside the bound the smaller tests assert, the reported quality and part volumes exact.
    check_elements(m, 5.0);
  }
}

// Figures for the report: the gravity compensator of Table 4.2 (hemisphere R 29 mm in a shell
// 30..43 mm, 1 mm gap, outer rotated by 30 deg about the x-axis) and its 178-cylinder variant.
TEST(Mesher3D, LongCompensatorTiming) {
  // MAGFEM_COMPENSATOR_VARIANT=0 or 1 runs one variant only (the gap of variant 0 is slow).
  const char* only = std::getenv("MAGFEM_COMPENSATOR_VARIANT");
  for (int variant = 0; variant < 2; ++variant) {
    if (only && std::atoi(only) != variant)
      continue;
    Geometry3D g = domain(100 * mm, 12 * mm, 0.02 * mm);
    g.parts.push_back(segment("inner", 0, 29 * mm, 0, pi / 2, 0, 2 * pi));
    g.parts[0].max_size = 4 * mm;
    if (variant == 0) {
      g.parts.push_back(segment("outer", 30 * mm, 43 * mm, 0, pi / 2, 0, 2 * pi));
      g.parts[1].max_size = 4 * mm;
      g.parts[1].placement =
          g.parts[1].placement.rotated(Eigen::Vector3d::UnitX(), pi / 6, Eigen::Vector3d::Zero());
    } else {
      // Rings of radially pointing cylinders r 2 mm, h 13 mm between 30 and 43 mm.
      int count = 0;
      for (double theta = 0.08; theta < pi / 2 - 0.05; theta += 0.155) {
        const int n = std::max(1, static_cast<int>(2 * pi * std::sin(theta) / 0.155));
        for (int k = 0; k < n && count < 178; ++k, ++count) {
          const double phi = 2 * pi * k / n;
          const Eigen::Vector3d dir(std::sin(theta) * std::cos(phi),
                                    std::sin(theta) * std::sin(phi), std::cos(theta));
          Part3D c;
          c.name = "cyl" + std::to_string(count);
          c.shape = Cylinder{0, 2 * mm, 13 * mm};
          c.max_size = 4 * mm;
          c.placement.rotation =
              Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), dir).toRotationMatrix();
          c.placement.translation = 30 * mm * dir;
          g.parts.push_back(c);
        }
      }
      std::printf("%d cylinders\n", count);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const Mesh3D m = build_mesh_3d(g);
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    print_figures(variant == 0 ? "compensator (outer at 30 deg)" : "compensator (cylinders)", m, s,
                  cpu);
    // The bound the smaller tests assert holds for the hemispheres (measured 6.0..165.8 deg);
    // among the 178 cylinders, with their thin gaps, TetGen leaves slivers down to 2.9 deg
    // (measured 2.9..175.6 at 30 M tets, the long tier's first run): bound 2.5 there, so a
    // mesher change that makes them worse fails here.
    check_elements(m, variant == 0 ? 5.0 : 2.5);
  }
}

// Meshing is safe on several threads (sweeps and studies mesh positions on a thread pool).
// TetGen's predicates keep global state: every call's exactinit() recomputes the machine
// epsilon and splitter in place and sizes the static filters of orient3d/insphere from its
// bounding box, so the mesher serializes its TetGen calls. Here a ball in a small domain is
// meshed on one thread while another thread meshes a case ten times larger again and again
// (a different bounding box, so filters 1000x apart); every mesh of either must be its serial
// mesh, node for node. Without the serialization a call can run with the other's filters or a
// half-computed splitter; the wrong predicate signs that follow are rare (not seen on this
// machine in 8 rounds with the lock removed), so this test can catch the race, not prove it
// absent.
void expect_same_mesh(const Mesh3D& a, const Mesh3D& reference, const std::string& what) {
  ASSERT_EQ(a.tets.size(), reference.tets.size()) << what;
  ASSERT_EQ(a.nodes.size(), reference.nodes.size()) << what;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    ASSERT_EQ(a.nodes[i], reference.nodes[i]) << what << " node " << i;
  for (std::size_t t = 0; t < a.tets.size(); ++t)
    ASSERT_EQ(a.tets[t], reference.tets[t]) << what << " tet " << t;
}

TEST(Mesher3D, MeshesBuiltOnTwoThreadsAtOnceEqualTheSerialMesh) {
  Geometry3D small = domain(20 * mm, 6 * mm, 0.05 * mm);
  small.parts.push_back(segment("ball", 0, 8 * mm, 0, pi, 0, 2 * pi));
  small.parts[0].max_size = 3 * mm;
  // Quick, so that the other thread starts many TetGen calls while the ball is meshed.
  Geometry3D large = domain(200 * mm, 80 * mm, 2 * mm);
  large.parts.push_back(segment("shell", 40 * mm, 70 * mm, 0, pi / 2, 0, 2 * pi));
  large.parts[0].max_size = 60 * mm;
  const Mesh3D small_reference = build_mesh_3d(small);
  const Mesh3D large_reference = build_mesh_3d(large);
  ASSERT_GT(small_reference.tets.size(), 100u);
  ASSERT_GT(large_reference.tets.size(), 100u);
  for (int round = 0; round < 8; ++round) {
    std::atomic<bool> done = false;
    int large_meshes = 0;
    std::thread other([&] {
      while (!done) {
        expect_same_mesh(build_mesh_3d(large), large_reference, "large");
        ++large_meshes;
      }
    });
    const Mesh3D a = build_mesh_3d(small);
    done = true;
    other.join();
    expect_same_mesh(a, small_reference, "small, round " + std::to_string(round));
    EXPECT_GT(large_meshes, 0);
  }
}

// Two spheres 1 mm apart, gap_layers 2, at a mesh scale, with adaptive sizes of adaptive_h
// along the gap's axis (0: none) and elements of an order: the mesher's gap warnings.
std::vector<std::string> gap_warnings(double scale, double adaptive_h = 0, int order = 1) {
  Geometry3D g = domain(20 * mm, 8 * mm, 0.1 * mm);
  g.options.gap_layers = 2;
  g.options.size_scale = scale;
  g.options.element_order = order;
  g.options.spheres_curved = order == 2; // as the pipeline sets it
  if (adaptive_h > 0) // sources along the gap's axis, from one sphere to the other
    g.options.refine_sizes = std::make_shared<const std::vector<SizeSample3D>>(
        std::vector<SizeSample3D>{{Vec3(6 * mm, 0, 0), adaptive_h},
                                  {Vec3(6.5 * mm, 0, 0), adaptive_h},
                                  {Vec3(7 * mm, 0, 0), adaptive_h}});
  g.parts.push_back(segment("ball", 0, 6 * mm, 0, pi, 0, 2 * pi));
  Part3D p = segment("other", 0, 5 * mm, 0, pi, 0, 2 * pi);
  p.placement.translation = Eigen::Vector3d(12 * mm, 0, 0); // 1 mm from "ball"
  g.parts.push_back(p);
  return build_mesh_3d(g).warnings;
}

// Issue 36: `--mesh-scale 2.5` with `gap_layers: 2` put elements larger than the gap across
// it, silently. Order 1: at scale 1 the gap has its 2 layers and nothing is said; at 2.5
// (1.25 mm across a 1 mm gap) the mesh warns, naming the gap and both parts. An adaptive pass
// that asks for small elements in the gap (refine_sizes) resolves it: no warning then,
// although the case's own sizes at that scale would leave it coarse.
TEST(Mesher3D, GapWiderThanItsOrderOneElementsIsWarnedAbout) {
  EXPECT_TRUE(gap_warnings(1.0).empty());
  const auto coarse = gap_warnings(2.5);
  ASSERT_EQ(coarse.size(), 1u);
  for (const char* text : {"1 mm air gap", "'ball'", "'other'", "order 1", "gap_layers 2",
                           "scaled by 2.5 in all", "at most 2 in all"})
    EXPECT_NE(coarse[0].find(text), std::string::npos) << text << " in: " << coarse[0];
  EXPECT_TRUE(gap_warnings(2.5, 0.4 * mm).empty());
  EXPECT_EQ(gap_warnings(2.5, 3 * mm).size(), 1u); // adaptive sizes coarser than the gap: still
}

// Issue 34: a P2 element of size h has nodes h / 2 apart, so the 1.25 mm elements of scale
// 2.5 put nodes 0.625 mm apart in the 1 mm gap: no warning (the compensator example's P2
// elements of 1.6 mm in its 1 mm gap gave its torque and force as closely as 0.8 mm ones did).
// Scale 5 (2.5 mm elements, nodes 1.25 mm apart) is still warned about, with the scale that
// would do (order x gap_layers = 4).
TEST(Mesher3D, GapIsWarnedAboutAtOrderTwoOnlyWhenItsNodesAreFartherApartThanItIsWide) {
  EXPECT_TRUE(gap_warnings(2.5, 0, 2).empty());
  const auto p2 = gap_warnings(5, 0, 2);
  ASSERT_EQ(p2.size(), 1u);
  for (const char* text : {"1 mm air gap", "order 2", "scaled by 5 in all", "at most 4 in all"})
    EXPECT_NE(p2[0].find(text), std::string::npos) << text << " in: " << p2[0];
}

} // namespace
} // namespace magfem
