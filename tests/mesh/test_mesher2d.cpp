// Properties of the 2D mesher: coverage and region areas, orientation and quality, chordal
// error, precedence of later parts, the air-gap rule, the conforming open-boundary shell,
// uniform refinement through size_scale, and errors that name the part.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "mesh/mesh_error.hpp"
#include "mesh/mesh_finish2d.hpp"
#include "mesh/mesher2d.hpp"
#include "mesh/region_map2d.hpp"
#include "mesh/region_overlap2d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;
constexpr double pi = std::numbers::pi;
// Sums of ~1e5 triangle areas: relative round-off well below 1e-12.
constexpr double area_rel_tol = 1e-11;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double triangle_area(const Mesh2D& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return 0.5 * cross(m.nodes[v[1]] - m.nodes[v[0]], m.nodes[v[2]] - m.nodes[v[0]]);
}

Vec2 centroid(const Mesh2D& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return (m.nodes[v[0]] + m.nodes[v[1]] + m.nodes[v[2]]) / 3.0;
}

double max_edge(const Mesh2D& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return std::max({(m.nodes[v[0]] - m.nodes[v[1]]).norm(), (m.nodes[v[1]] - m.nodes[v[2]]).norm(),
                   (m.nodes[v[2]] - m.nodes[v[0]]).norm()});
}

std::map<int, double> region_areas(const Mesh2D& m) {
  std::map<int, double> a;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    a[m.triangle_part[t]] += triangle_area(m, t);
  return a;
}

// Area of the polygon through the mesh nodes lying exactly on a circle (the chord vertices of
// the outline; vertices CGAL adds lie on the chords, inside the circle, and do not change it).
double circle_polygon_area(const Mesh2D& m, const Vec2& c, double r, int* n_vertices = nullptr) {
  std::vector<double> angles;
  for (const Vec2& p : m.nodes)
    if (std::abs((p - c).norm() - r) <= 1e-12 * r)
      angles.push_back(std::atan2(p.y() - c.y(), p.x() - c.x()));
  std::sort(angles.begin(), angles.end());
  double a = 0;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * pi;
    a += 0.5 * r * r * std::sin(next - angles[i]);
  }
  if (n_vertices)
    *n_vertices = int(angles.size());
  return a;
}

Geometry2D base_geometry(OuterKind kind, double radius) {
  Geometry2D g;
  g.outer = {kind, radius, 1.5};
  g.options.default_size = 2 * mm;
  g.options.chord_tolerance = 0.01 * mm;
  return g;
}

void expect_ccw_and_quality(const Mesh2D& m, double min_angle_deg) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    ASSERT_GT(triangle_area(m, t), 0.0) << t;
  EXPECT_GT(m.quality.min_area, 0.0);
  EXPECT_GE(m.quality.min_angle_deg, min_angle_deg);
  EXPECT_LT(m.quality.max_angle_deg, 180.0 - 2 * min_angle_deg + 1e-9);
}

TEST(Mesher2D, DiskInOpenSpaceCoversDomainWithQualityAndChordalBound) {
  Geometry2D g = base_geometry(OuterKind::open, 20 * mm);
  g.parts.push_back({"magnet", Disk{Vec2(1 * mm, -2 * mm), 8 * mm}, 0.5 * mm});
  const Mesh2D m = build_mesh_2d(g);

  // Promised bound: min(min_angle_deg = 28, 30); the geometry has no sharp input corners.
  expect_ccw_and_quality(m, 28.0);
  EXPECT_LE(m.quality.max_sagitta, g.options.chord_tolerance);

  // Each region tiles its polygon: polygon area to round-off, exact area within the chordal
  // bound (an inscribed polygon with sagitta s loses at most perimeter * s).
  const auto areas = region_areas(m);
  const double r = 8 * mm, s = m.quality.max_sagitta;
  const double magnet_poly = circle_polygon_area(m, Vec2(1 * mm, -2 * mm), r);
  EXPECT_NEAR(areas.at(0), magnet_poly, area_rel_tol * magnet_poly);
  EXPECT_LE(pi * r * r - areas.at(0), 2 * pi * r * s);
  EXPECT_GE(pi * r * r - areas.at(0), 0.0);
  int n1 = 0;
  const double r1 = 20 * mm, domain_poly = circle_polygon_area(m, Vec2::Zero(), r1, &n1);
  EXPECT_NEAR(areas.at(0) + areas.at(region_background), domain_poly, area_rel_tol * domain_poly);
  EXPECT_LE(pi * r1 * r1 - domain_poly, 2 * pi * r1 * s);
  const double r2 = 30 * mm, all_poly = circle_polygon_area(m, Vec2::Zero(), r2);
  EXPECT_NEAR(areas.at(region_shell), all_poly - domain_poly, area_rel_tol * all_poly);

  // Magnet chords: sagitta within tolerance and length within the magnet's size.
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.triangle_part[t] != 0)
      continue;
    const auto& v = m.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = m.nodes[v[k]] - Vec2(1 * mm, -2 * mm),
                 b = m.nodes[v[(k + 1) % 3]] - Vec2(1 * mm, -2 * mm);
      if (std::abs(a.norm() - r) > 1e-12 * r || std::abs(b.norm() - r) > 1e-12 * r)
        continue;
      EXPECT_LE(r - (0.5 * (a + b)).norm(), g.options.chord_tolerance * (1 + 1e-9));
      EXPECT_LE((a - b).norm(), 0.5 * mm * (1 + 1e-9));
    }
  }
}

TEST(Mesher2D, OpenShellIsConformingAndOuterEdgesLieOnOuterCircle) {
  Geometry2D g = base_geometry(OuterKind::open, 20 * mm);
  g.parts.push_back({"magnet", Disk{Vec2::Zero(), 10 * mm}, 1 * mm});
  const Mesh2D m = build_mesh_2d(g);
  const double r1 = 20 * mm, r2 = 30 * mm;
  EXPECT_DOUBLE_EQ(m.shell_inner_radius, r1);
  EXPECT_DOUBLE_EQ(m.shell_outer_radius, r2);

  // Every edge on the R1 circle has one inside and one shell triangle.
  std::map<std::pair<int, int>, std::vector<int>> edge_parts;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      edge_parts[{std::min(a, b), std::max(a, b)}].push_back(m.triangle_part[t]);
    }
  const auto on = [&](int v, double r) { return std::abs(m.nodes[v].norm() - r) <= 1e-12 * r; };
  int n_r1 = 0;
  for (const auto& [e, parts] : edge_parts) {
    if (!on(e.first, r1) || !on(e.second, r1))
      continue;
    ++n_r1;
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(std::count(parts.begin(), parts.end(), region_shell), 1);
  }
  EXPECT_GE(n_r1, 8);
  // No inside triangle reaches beyond R1, no shell triangle inside it.
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const double rc = centroid(m, t).norm();
    if (m.triangle_part[t] == region_shell) {
      EXPECT_GT(rc, r1 * std::cos(pi / n_r1) * (1 - 1e-12));
      // At least 4 layers radially: no shell edge longer than (R2 - R1) / 4.
      EXPECT_LE(max_edge(m, t), 0.25 * (r2 - r1) * (1 + 1e-9));
    } else {
      EXPECT_LT(rc, r1);
    }
  }
  // Outer edges: on R2 exactly, counter-clockwise (domain on the left), closing the circle.
  double turned = 0;
  for (const auto& e : m.outer_edges) {
    EXPECT_TRUE(on(e[0], r2) && on(e[1], r2));
    const Vec2 a = m.nodes[e[0]], b = m.nodes[e[1]];
    EXPECT_GT(cross(a, b), 0.0);
    turned += std::atan2(cross(a, b), a.dot(b));
  }
  EXPECT_NEAR(turned, 2 * pi, 1e-9);
}

TEST(Mesher2D, DirichletBoundaryHasNoShellAndOuterEdgesOnDomainCircle) {
  Geometry2D g = base_geometry(OuterKind::dirichlet, 20 * mm);
  g.parts.push_back({"steel", Annulus{Vec2::Zero(), 12 * mm, 16 * mm}, 1 * mm});
  const Mesh2D m = build_mesh_2d(g);
  EXPECT_EQ(m.shell_inner_radius, 0.0);
  for (int r : m.triangle_part)
    EXPECT_NE(r, region_shell);
  for (const auto& e : m.outer_edges)
    for (int v : e)
      EXPECT_NEAR(m.nodes[v].norm(), 20 * mm, 1e-12 * 20 * mm);
  int n = 0;
  const double poly = circle_polygon_area(m, Vec2::Zero(), 20 * mm, &n);
  EXPECT_EQ(int(m.outer_edges.size()), n);
  const auto areas = region_areas(m);
  EXPECT_NEAR(areas.at(0) + areas.at(region_background), poly, area_rel_tol * poly);
  const double annulus_poly =
      circle_polygon_area(m, Vec2::Zero(), 16 * mm) - circle_polygon_area(m, Vec2::Zero(), 12 * mm);
  EXPECT_NEAR(areas.at(0), annulus_poly, area_rel_tol * annulus_poly);
}

TEST(Mesher2D, LaterPartsTakePrecedence) {
  Geometry2D g = base_geometry(OuterKind::neumann, 40 * mm);
  g.parts.push_back({"yoke", Rectangle{Vec2::Zero(), 30 * mm, 16 * mm, 0.0}, 1 * mm});
  g.parts.push_back({"inset", Disk{Vec2(-5 * mm, 0), 4 * mm}, 0.5 * mm, true});
  // Straddles the right edge; off-centre so that no split point of that edge lies on its circle
  // (circle_polygon_area collects every node on the circle).
  g.parts.push_back({"cap", Disk{Vec2(15 * mm, 0.37 * mm), 3 * mm}, 0, true});
  const Mesh2D m = build_mesh_2d(g);
  expect_ccw_and_quality(m, 28.0);
  const auto areas = region_areas(m);
  const double inset = circle_polygon_area(m, Vec2(-5 * mm, 0), 4 * mm);
  const double cap = circle_polygon_area(m, Vec2(15 * mm, 0.37 * mm), 3 * mm);
  EXPECT_NEAR(areas.at(1), inset, area_rel_tol * inset);
  EXPECT_NEAR(areas.at(2), cap, area_rel_tol * cap);
  // The yoke keeps its rectangle minus the inset and the left part of the cap, which is about
  // half the cap polygon (vertex placement breaks the symmetry by far less than 0.1 %) and at
  // most the exact half disk.
  const double yoke_min = 30 * mm * 16 * mm - inset - 0.5 * pi * 9 * mm * mm;
  const double yoke_max = 30 * mm * 16 * mm - inset - 0.5 * cap + 1e-3 * cap;
  EXPECT_GT(areas.at(0), yoke_min);
  EXPECT_LT(areas.at(0), yoke_max);
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const Vec2 c = centroid(m, t);
    if ((c - Vec2(-5 * mm, 0)).norm() < 3.9 * mm) {
      EXPECT_EQ(m.triangle_part[t], 1);
    }
    if ((c - Vec2(15 * mm, 0.37 * mm)).norm() < 2.9 * mm) {
      EXPECT_EQ(m.triangle_part[t], 2);
    }
  }
}

TEST(Mesher2D, EveryPrimitiveMatchesItsExactAreaWithinTheChordalBound) {
  Geometry2D g = base_geometry(OuterKind::open, 50 * mm);
  g.parts.push_back({"disk", Disk{Vec2(-25 * mm, 0), 6 * mm}, 1 * mm});
  g.parts.push_back({"ring", Annulus{Vec2(0, 20 * mm), 3 * mm, 7 * mm}, 1 * mm});
  g.parts.push_back(
      {"sector", AnnularSector{Vec2(10 * mm, -10 * mm), 4 * mm, 12 * mm, 0.2, 2.0}, 1 * mm});
  g.parts.push_back({"pie", AnnularSector{Vec2(-10 * mm, -25 * mm), 0, 8 * mm, -1.0, 0.5}, 1 * mm});
  g.parts.push_back({"bar", Rectangle{Vec2(25 * mm, 20 * mm), 10 * mm, 4 * mm, 0.5}, 0});
  g.parts.push_back(
      {"tri", Polygon{{Vec2(30 * mm, -5 * mm), Vec2(40 * mm, -5 * mm), Vec2(35 * mm, 5 * mm)}}, 0});
  // A clockwise 20-point star (tips of 34 deg): exercises the banded containment test.
  Polygon star;
  double star_area = 0;
  for (int k = 0; k < 40; ++k) {
    const double a = -2 * pi * k / 40, r = (k % 2 ? 4 : 6) * mm;
    star.vertices.push_back(Vec2(-25 * mm, 25 * mm) + r * Vec2(std::cos(a), std::sin(a)));
  }
  for (int k = 0; k < 40; ++k)
    star_area -= 0.5 * cross(star.vertices[k], star.vertices[(k + 1) % 40]) / (mm * mm);
  g.parts.push_back({"star", star, 0});
  const Mesh2D m = build_mesh_2d(g);
  // The pie's apex angle (1.5 rad = 86 deg) and the sector's corners (90 deg) are not sharp.
  expect_ccw_and_quality(m, 28.0);
  const auto areas = region_areas(m);
  const double s = m.quality.max_sagitta;
  // Exact areas and the arc lengths that bound the chordal deficit (arc length * sagitta).
  const double exact[] = {pi * 36, pi * (49 - 9), 0.5 * 1.8 * (144 - 16), 0.5 * 1.5 * 64, 40,
                          50,      star_area};
  const double arcs[] = {2 * pi * 6, 2 * pi * 10, 1.8 * 16, 1.5 * 8, 0, 0, 0};
  for (int i = 0; i < 7; ++i) // outer chords cut area off, inner chords (holes) add some
    EXPECT_NEAR(areas.at(i) / (mm * mm), exact[i], arcs[i] * s / mm + area_rel_tol * exact[i])
        << g.parts[i].name;
}

TEST(Mesher2D, PartsMeetingOnACircleShareItsVertices) {
  // A six-pole magnet ring on a yoke: sectors side by side and on the yoke's outer circle. Were
  // the polygons cut independently they would cross in slivers of the sagitta's width.
  Geometry2D g = base_geometry(OuterKind::open, 25 * mm);
  g.parts.push_back({"yoke", Annulus{Vec2::Zero(), 5 * mm, 8 * mm}, 1 * mm});
  for (int k = 0; k < 6; ++k)
    g.parts.push_back(
        {"pole" + std::to_string(k),
         AnnularSector{Vec2::Zero(), 8 * mm, 10 * mm, 0.3 + pi * k / 3, 0.3 + pi * (k + 1) / 3},
         0.7 * mm});
  const Mesh2D m = build_mesh_2d(g);
  expect_ccw_and_quality(m, 28.0);
  const auto areas = region_areas(m);
  const double s = m.quality.max_sagitta;
  // Each pole: exact area within the chordal bound of its two arcs (the outer chords cut area
  // off, the inner chords add some).
  const double pole = pi / 6 * (100 - 64);
  for (int k = 1; k <= 6; ++k)
    EXPECT_NEAR(areas.at(k) / (mm * mm), pole, pi / 3 * 18 * s / mm) << k;
  // The ring and the yoke share the 8 mm polygon: together they tile the 10 mm polygon minus
  // the 5 mm one, to round-off.
  double ring = 0;
  for (int k = 0; k <= 6; ++k)
    ring += areas.at(k);
  const double tiled =
      circle_polygon_area(m, Vec2::Zero(), 10 * mm) - circle_polygon_area(m, Vec2::Zero(), 5 * mm);
  EXPECT_NEAR(ring, tiled, area_rel_tol * tiled);
  const double yoke =
      circle_polygon_area(m, Vec2::Zero(), 8 * mm) - circle_polygon_area(m, Vec2::Zero(), 5 * mm);
  EXPECT_NEAR(areas.at(0), yoke, area_rel_tol * yoke);
  // No element is much smaller than the sizes asked for (a sliver would force tiny ones).
  EXPECT_GT(m.quality.min_area, 0.01 * 0.7 * mm * 0.7 * mm);
}

TEST(Mesher2D, SizesGradeAwayFromAFinePart) {
  // A 0.1 mm part in 4 mm air: with slope 0.5 an air element whose centroid lies at distance r
  // from the part's polygon is at most 0.1 mm + 0.5 r long (CGAL's quality refinement can only
  // make it smaller). r is bounded by the distance to the circle plus the sagitta.
  Geometry2D g = base_geometry(OuterKind::dirichlet, 30 * mm);
  g.options.default_size = 4 * mm;
  const Vec2 c(2 * mm, 1 * mm);
  g.parts.push_back({"wire", Disk{c, 1 * mm}, 0.1 * mm});
  const Mesh2D m = build_mesh_2d(g);
  double max_ratio = 0;
  int n_far = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.triangle_part[t] != region_background)
      continue;
    const double r = std::max(0.0, (centroid(m, t) - c).norm() - 1 * mm + m.quality.max_sagitta);
    max_ratio = std::max(max_ratio, max_edge(m, t) / (0.1 * mm + 0.5 * r));
    if (max_edge(m, t) > 2 * mm)
      ++n_far;
  }
  EXPECT_LE(max_ratio, 1.0 + 1e-9);
  EXPECT_GT(n_far, 0); // the air does coarsen to its own size far away
}

TEST(Mesher2D, TouchingPartsStayCheap) {
  // A disk resting on a rectangle: their outlines touch at one point, where the rectangle's
  // split point and the disk's lowest chord vertex are a hair apart. They are merged, and the
  // cusp narrower than 3 chord tolerances counts as contact, so the mesh stays small.
  Geometry2D g = base_geometry(OuterKind::open, 25 * mm);
  g.parts.push_back({"plate", Rectangle{Vec2(0, -3 * mm), 10 * mm, 6 * mm, 0}, 0.5 * mm});
  g.parts.push_back({"disk", Disk{Vec2(0, 2 * mm), 2 * mm}, 0.5 * mm});
  const Mesh2D m = build_mesh_2d(g);
  EXPECT_LT(m.n_triangles(), 60000u); // ~43k; unmerged, femtometre features cost millions
  EXPECT_GT(m.quality.min_area, 0.0);
  const auto areas = region_areas(m);
  // The merge moves a vertex by < 1e-9 m, changing areas by far less than 1e-8 relative.
  EXPECT_NEAR(areas.at(0), 60 * mm * mm, 1e-8 * 60 * mm * mm);
  EXPECT_NEAR(areas.at(1), pi * 4 * mm * mm, 2 * pi * 2 * mm * m.quality.max_sagitta);
}

// Share of a segment's length inside a triangle (Cyrus-Beck clipping).
double clipped_length(const Mesh2D& m, std::size_t t, const Vec2& p, const Vec2& q) {
  double t0 = 0, t1 = 1;
  const auto& v = m.triangles[t];
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = m.nodes[v[k]], b = m.nodes[v[(k + 1) % 3]];
    const double num = cross(b - a, p - a), den = cross(b - a, q - p); // inside: cross >= 0
    if (den == 0) {
      if (num < 0)
        return 0;
    } else if (den > 0) {
      t0 = std::max(t0, -num / den);
    } else {
      t1 = std::min(t1, -num / den);
    }
  }
  return t1 > t0 ? (t1 - t0) * (q - p).norm() : 0;
}

TEST(Mesher2D, ThinAirGapGetsAtLeastThreeLayers) {
  Geometry2D g = base_geometry(OuterKind::open, 25 * mm);
  const double r_in = 10 * mm, gap = 0.3 * mm;
  g.parts.push_back({"rotor", Annulus{Vec2::Zero(), 5 * mm, r_in}, 1 * mm});
  g.parts.push_back({"stator", Annulus{Vec2::Zero(), r_in + gap, 15 * mm}, 1 * mm});
  const Mesh2D m = build_mesh_2d(g);
  ASSERT_EQ(g.options.gap_layers, 3);
  expect_ccw_and_quality(m, 28.0);
  // The polygons' gap differs from 0.3 mm by at most the sagitta of each side.
  const double d_max = gap + 2 * m.quality.max_sagitta;
  int n_gap = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const double rc = centroid(m, t).norm();
    if (m.triangle_part[t] != region_background || rc < r_in - gap || rc > r_in + 2 * gap)
      continue;
    ++n_gap;
    EXPECT_LE(max_edge(m, t), d_max / 3) << t;
  }
  EXPECT_GT(n_gap, 1000);
  // Count the air triangles a radial line crosses inside the gap.
  for (int k = 0; k < 16; ++k) {
    const double phi = 0.1 + 2 * pi * k / 16;
    const Vec2 dir(std::cos(phi), std::sin(phi));
    const Vec2 p = (r_in - gap) * dir, q = (r_in + 2 * gap) * dir;
    int layers = 0;
    for (std::size_t t = 0; t < m.n_triangles(); ++t)
      if (m.triangle_part[t] == region_background && clipped_length(m, t, p, q) > 1e-6 * gap)
        ++layers;
    EXPECT_GE(layers, 3) << "phi = " << phi;
  }
  // Away from the gap the air keeps its coarse size: the rule is local.
  double far_max = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.triangle_part[t] == region_background && centroid(m, t).norm() > 20 * mm)
      far_max = std::max(far_max, max_edge(m, t));
  EXPECT_GT(far_max, 1 * mm);
}

TEST(Mesher2D, HalvingSizeScaleRoughlyQuadruplesTriangles) {
  Geometry2D g = base_geometry(OuterKind::open, 20 * mm);
  g.options.chord_tolerance = 0.1 * mm; // sizes, not the tolerance, set the chords
  g.parts.push_back({"magnet", Disk{Vec2::Zero(), 10 * mm}, 1 * mm});
  const Mesh2D coarse = build_mesh_2d(g);
  g.options.size_scale = 0.5;
  const Mesh2D fine = build_mesh_2d(g);
  const double ratio = double(fine.n_triangles()) / double(coarse.n_triangles());
  // 4 for a self-similar mesh; boundary layers and CGAL's refinement order move it slightly.
  EXPECT_GT(ratio, 3.4);
  EXPECT_LT(ratio, 4.6);
}

TEST(MeshFinish2D, SliverIsRemovedBySplittingItsNeighbour) {
  // c lies a hair above edge a-b: the flat triangle (a, b, c) goes, (b, a, y) is split at c.
  Mesh2D m;
  m.nodes = {Vec2(0, 0), Vec2(2, 0), Vec2(1, 1e-13), Vec2(1, -1), Vec2(1, 1)}; // a b c y x
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 2, 4}, {2, 1, 4}};
  m.triangle_part = {7, 5, 6, 6};
  Neighbours2D nb = neighbours(m);
  EXPECT_EQ(remove_slivers(m, nb), 1);
  ASSERT_EQ(m.n_triangles(), 4u);
  double area = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    EXPECT_GT(triangle_area(m, t), 0.25);
    EXPECT_NE(m.triangle_part[t], 7);
    area += triangle_area(m, t);
  }
  EXPECT_NEAR(area, 2.0, 1e-12);
  EXPECT_EQ(nb, neighbours(m)); // the adjacency was kept up to date
  EXPECT_EQ(boundary_edges(m, nb).size(), 4u);
  EXPECT_EQ(interface_edges(m, nb, 5).size(), 2u); // the two halves of a-b
}

template <class F>
void expect_mesh_error(F&& make, const std::string& part, const std::string& field) {
  try {
    make();
    FAIL() << "no MeshError for part '" << part << "'";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.part, part) << e.what();
    EXPECT_EQ(e.field, field) << e.what();
    if (!part.empty()) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos);
    }
  }
}

TEST(Mesher2D, BadInputThrowsMeshErrorNamingThePart) {
  const auto with = [](Part2D p) {
    Geometry2D g = base_geometry(OuterKind::open, 20 * mm);
    g.parts.push_back({"ok", Disk{Vec2::Zero(), 2 * mm}, 0});
    g.parts.push_back(std::move(p));
    return g;
  };
  expect_mesh_error([&] { build_mesh_2d(with({"m1", Disk{Vec2::Zero(), 0}, 0})); }, "m1", "radius");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"m2", Annulus{Vec2::Zero(), 5 * mm, 5 * mm}, 0}));
      },
      "m2", "r_inner");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"m3", AnnularSector{Vec2::Zero(), 1 * mm, 5 * mm, 1.0, 1.0}, 0}));
      },
      "m3", "angle_end");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"m4", Rectangle{Vec2::Zero(), 0, 1 * mm, 0}, 0}));
      },
      "m4", "width");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"m5", Polygon{{Vec2::Zero(), Vec2(1 * mm, 0)}}, 0}));
      },
      "m5", "vertices");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with(
            {"bowtie",
             Polygon{{Vec2(0, 0), Vec2(4 * mm, 4 * mm), Vec2(4 * mm, 0), Vec2(0, 4 * mm)}}, 0}));
      },
      "bowtie", "vertices");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"far", Disk{Vec2(18 * mm, 0), 3 * mm}, 0}));
      },
      "far", "");
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"neg", Disk{Vec2::Zero(), 1 * mm}, -1.0}));
      },
      "neg", "max_size");
  // "ok" (a 2 mm disk) is covered completely by the later 5 mm disk.
  expect_mesh_error(
      [&] {
        build_mesh_2d(with({"cover", Disk{Vec2::Zero(), 5 * mm}, 0, true}));
      },
      "ok", "");
  Geometry2D g = with({"fine", Disk{Vec2(5 * mm, 0), 1 * mm}, 0});
  g.options.default_size = 0;
  expect_mesh_error([&] { build_mesh_2d(g); }, "", "default_size");
}

// Overlap is an error naming both parts, the exact shared area and where, unless the later
// part replaces. A 5 x 5 mm magnet and a coil rectangle 1 mm into it over 4 mm share exactly
// 4 mm^2 (straight edges: the outlines are exact, and the area is computed exactly, so the
// 1e-9 tolerance is round-off of the mm -> m conversion only).
TEST(Mesher2D, OverlapIsAnErrorNamingBothPartsUnlessTheLaterReplaces) {
  Geometry2D g = base_geometry(OuterKind::open, 30 * mm);
  g.parts.push_back({"magnet", Rectangle{Vec2::Zero(), 5 * mm, 5 * mm, 0.0}, 1 * mm});
  g.parts.push_back({"coil", Rectangle{Vec2(4 * mm, 0.5 * mm), 5 * mm, 4 * mm, 0.0}, 1 * mm});
  try {
    build_mesh_2d(g);
    ADD_FAILURE() << "overlap accepted";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.part, "coil");
    EXPECT_NE(e.reason.find("region 'coil' overlaps region 'magnet' (4 mm^2 around"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.reason.find("overlap: replace"), std::string::npos) << e.what();
  }
  // The shared area itself, exact for straight outlines.
  std::vector<Outline2D> outlines;
  {
    const RegionMap2D map(g, [](int, const Vec2&) { return 1 * mm; });
    const auto o = find_region_overlap2d(g.parts, {map.part(0), map.part(1)});
    ASSERT_TRUE(o);
    EXPECT_EQ(o->earlier, 0u);
    EXPECT_EQ(o->later, 1u);
    EXPECT_NEAR(o->area, 4 * mm * mm, 1e-9 * 4 * mm * mm);
    EXPECT_GT(o->point.x(), 1.5 * mm);
    EXPECT_LT(o->point.x(), 2.5 * mm);
  }
  // With replace the coil takes the 4 mm^2: the magnet keeps 21 mm^2.
  g.parts[1].replace_earlier = true;
  const auto areas = region_areas(build_mesh_2d(g));
  EXPECT_NEAR(areas.at(0), 21 * mm * mm, area_rel_tol * 25 * mm * mm);
  EXPECT_NEAR(areas.at(1), 20 * mm * mm, area_rel_tol * 20 * mm * mm);
}

// Parts that only touch share no area: along an edge (rectangles of different lengths, whose
// edge split points differ), a disk in an annulus's hole (a shared circle), a sector beside a
// sector, and two disks tangent to each other (inscribed chords stay apart).
TEST(Mesher2D, TouchingPartsAreNoOverlap) {
  Geometry2D g = base_geometry(OuterKind::open, 40 * mm);
  g.parts.push_back({"base", Rectangle{Vec2(0, -2 * mm), 20 * mm, 4 * mm, 0.0}, 1 * mm});
  g.parts.push_back({"top", Rectangle{Vec2(1.3 * mm, 1.5 * mm), 7 * mm, 3 * mm, 0.0}, 0.7 * mm});
  g.parts.push_back({"shaft", Disk{Vec2(0, 15 * mm), 3 * mm}, 0.5 * mm});
  g.parts.push_back({"rotor", Annulus{Vec2(0, 15 * mm), 3 * mm, 6 * mm}, 0.5 * mm});
  g.parts.push_back({"s1", AnnularSector{Vec2(0, -20 * mm), 2 * mm, 6 * mm, 0.0, 1.0}, 0});
  g.parts.push_back({"s2", AnnularSector{Vec2(0, -20 * mm), 2 * mm, 6 * mm, 1.0, 2.0}, 0});
  g.parts.push_back({"d1", Disk{Vec2(20 * mm, 0), 3 * mm}, 0});
  g.parts.push_back({"d2", Disk{Vec2(26 * mm, 0), 3 * mm}, 0});
  EXPECT_NO_THROW(build_mesh_2d(g));
}

// Speed figure (long tier: bash scripts/test.sh --long): about 50k triangles. CPU time is
// asserted because the wall time depends on what else the shared machine runs.
TEST(Mesher2D, LongBenchmark50kTriangles) {
  Geometry2D g = base_geometry(OuterKind::open, 20 * mm);
  g.options.default_size = 0.5 * mm;
  g.parts.push_back({"magnet", Disk{Vec2::Zero(), 10 * mm}, 0});
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const Mesh2D m = build_mesh_2d(g);
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("mesher2d: %zu nodes, %zu triangles in %.3f s wall, %.3f s CPU, min angle %.2f "
              "deg, max %.2f deg\n",
              m.n_nodes(), m.n_triangles(), s, cpu, m.quality.min_angle_deg,
              m.quality.max_angle_deg);
  EXPECT_LT(cpu, 1.0);
}

} // namespace
} // namespace magfem
