// CAD parts from STL files (mesh/stl_reader3d): ASCII and binary give the same surface, bad
// orientations are repaired outward, and every bad surface is refused with its file named.
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include "mesh/mesh_error.hpp"
#include "mesh/stl_reader3d.hpp"
#include "mesh/surface_index3d.hpp"
#include "tests/mesh/stl_test_files.hpp"

using namespace magfem;
using test::TriSurface;

namespace {

std::string temp_path(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests" / "stl";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// Enclosed volume by the divergence theorem: positive for outward triangles.
double signed_volume(const TriangleSurface& s) {
  double v = 0;
  for (const auto& t : s.triangles)
    v += s.points[t[0]].dot(s.points[t[1]].cross(s.points[t[2]])) / 6;
  return v;
}

// The reader's message for the surface, or "" when it is accepted.
std::string refusal(const TriSurface& s, const std::string& name) {
  const std::string path = temp_path(name);
  test::write_ascii_stl(path, s);
  try {
    read_stl_surface(path, 1e-3);
  } catch (const MeshError& e) {
    EXPECT_EQ(e.field, "file");
    EXPECT_NE(e.reason.find(path), std::string::npos) << e.reason;
    return e.reason;
  }
  return "";
}

std::string refusal_of_file(const std::string& path) {
  try {
    read_stl_surface(path, 1e-3);
  } catch (const MeshError& e) {
    EXPECT_NE(e.reason.find(path), std::string::npos) << e.reason;
    return e.reason;
  }
  return "";
}

bool says(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

} // namespace

// The same float coordinates either way: the same points and triangles, bit for bit. The
// volume of the 320-triangle icosphere of radius 10 mm against its exact polyhedral volume
// (sum of the tetrahedra from the centre, in double) to float round-off: the mm-to-m scale and
// the outward orientation are checked with it.
TEST(StlReader, AsciiAndBinaryGiveTheSameOutwardSurface) {
  const TriSurface sphere = test::icosphere(10, 2);
  const std::string ascii = temp_path("sphere_ascii.stl"), binary = temp_path("sphere_bin.stl"),
                    solid_header = temp_path("sphere_solid_header.stl");
  test::write_ascii_stl(ascii, sphere);
  test::write_binary_stl(binary, sphere);
  test::write_binary_stl(solid_header, sphere, "solid exported by a CAD system");
  const TriangleSurface a = read_stl_surface(ascii, 1e-3);
  const TriangleSurface b = read_stl_surface(binary, 1e-3);
  const TriangleSurface c = read_stl_surface(solid_header, 1e-3);
  ASSERT_EQ(a.points.size(), sphere.points.size());
  ASSERT_EQ(a.triangles.size(), sphere.triangles.size());
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.points, c.points);
  double exact = 0;
  for (const auto& t : sphere.triangles)
    exact += sphere.points[t[0]].dot(sphere.points[t[1]].cross(sphere.points[t[2]])) / 6;
  EXPECT_NEAR(signed_volume(a) / (exact * 1e-9), 1.0, 1e-6);
  EXPECT_TRUE(a.index->contains(a.inside_point, 0));
  EXPECT_LT(a.index->distance(a.inside_point), 1e-5);
  EXPECT_TRUE(a.index->contains(Vec3::Zero(), -9e-3));
  EXPECT_FALSE(a.index->contains(Vec3(0, 0, 10.5e-3), 0));
  EXPECT_TRUE(a.index->contains(Vec3(0, 0, 10.5e-3), 1e-3));
  // file_unit: the same file read in metres is a thousand times larger.
  const TriangleSurface m = read_stl_surface(ascii, 1.0);
  EXPECT_NEAR(signed_volume(m) / signed_volume(a), 1e9, 1e3);
}

// Exporters write inward or mixed orientations: the part is the same either way.
TEST(StlReader, InwardAndMixedOrientationsAreTurnedOutward) {
  const TriSurface sphere = test::icosphere(10, 1);
  TriSurface inward = sphere, mixed = sphere;
  for (auto& t : inward.triangles)
    std::swap(t[1], t[2]);
  for (std::size_t i = 0; i < mixed.triangles.size(); i += 3)
    std::swap(mixed.triangles[i][1], mixed.triangles[i][2]);
  const std::string pi = temp_path("inward.stl"), pm = temp_path("mixed.stl"),
                    po = temp_path("outward.stl");
  test::write_ascii_stl(pi, inward);
  test::write_ascii_stl(pm, mixed);
  test::write_ascii_stl(po, sphere);
  const double v = signed_volume(read_stl_surface(po, 1e-3));
  EXPECT_GT(v, 0);
  for (const std::string& p : {pi, pm}) {
    const TriangleSurface s = read_stl_surface(p, 1e-3);
    EXPECT_NEAR(signed_volume(s), v, 1e-9 * v) << p;
    EXPECT_TRUE(s.index->contains(Vec3::Zero(), 0)) << p;
  }
}

TEST(StlReader, OpenSurfaceIsRefused) {
  TriSurface s = test::icosphere(10, 1);
  s.triangles.pop_back();
  const std::string why = refusal(s, "open.stl");
  EXPECT_TRUE(says(why, "not closed") && says(why, "3 edges")) << why;
}

TEST(StlReader, SelfIntersectingSurfaceIsRefused) {
  TriSurface s = test::icosphere(10, 1);
  s.points[0] *= -1.5; // its fan of triangles now pierces the far side
  const std::string why = refusal(s, "self_intersecting.stl");
  EXPECT_TRUE(says(why, "intersects itself")) << why;
}

TEST(StlReader, NonManifoldSurfacesAreRefused) {
  // A fin: a third triangle on an edge of the sphere.
  TriSurface fin = test::icosphere(10, 1);
  fin.points.emplace_back(0, 0, 30);
  fin.triangles.push_back(
      {fin.triangles[0][0], fin.triangles[0][1], static_cast<int>(fin.points.size()) - 1});
  EXPECT_TRUE(says(refusal(fin, "fin.stl"), "shared by 3 triangles"));
  // Two spheres touching at one corner (the second the first reflected through it).
  TriSurface pair = test::icosphere(10, 1);
  const int n = static_cast<int>(pair.points.size());
  const Eigen::Vector3d v0 = pair.points[0];
  for (int i = 0; i < n; ++i)
    pair.points.push_back(2 * v0 - pair.points[i]);
  const std::size_t nt = pair.triangles.size();
  for (std::size_t t = 0; t < nt; ++t) {
    auto tri = pair.triangles[t];
    for (int& k : tri)
      k = k == 0 ? 0 : k + n;
    pair.triangles.push_back(tri);
  }

  const std::string why = refusal(pair, "touching.stl");
  EXPECT_TRUE(says(why, "not a manifold") && says(why, "separate sheets")) << why;
}

TEST(StlReader, SeveralBodiesAreRefused) {
  TriSurface two = test::icosphere(10, 1);
  const int n = static_cast<int>(two.points.size());
  for (int i = 0; i < n; ++i)
    two.points.push_back(two.points[i] + Eigen::Vector3d(30, 0, 0));
  const std::size_t nt = two.triangles.size();
  for (std::size_t t = 0; t < nt; ++t)
    two.triangles.push_back(
        {two.triangles[t][0] + n, two.triangles[t][1] + n, two.triangles[t][2] + n});
  EXPECT_TRUE(says(refusal(two, "two_bodies.stl"), "2 separate pieces"));
}

TEST(StlReader, DegenerateTriangleIsRefused) {
  TriSurface s = test::icosphere(10, 1);
  const auto t = s.triangles[0];
  s.points.push_back(0.5 * (s.points[t[0]] + s.points[t[1]]));
  s.triangles.push_back({t[0], t[1], static_cast<int>(s.points.size()) - 1});
  EXPECT_TRUE(says(refusal(s, "degenerate.stl"), "has no area"));
}

TEST(StlReader, UnreadableEmptyAndConfusedFilesAreRefused) {
  EXPECT_TRUE(says(refusal_of_file(temp_path("does_not_exist.stl")), "cannot read"));
  const std::string empty = temp_path("empty.stl");
  std::ofstream(empty).close();
  EXPECT_TRUE(says(refusal_of_file(empty), "is empty"));
  const std::string no_facets = temp_path("no_facets.stl");
  std::ofstream(no_facets) << "solid nothing\nendsolid nothing\n";
  EXPECT_TRUE(says(refusal_of_file(no_facets), "no triangles"));
  const std::string broken = temp_path("broken_ascii.stl");
  std::ofstream(broken) << "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 1\n";
  EXPECT_TRUE(says(refusal_of_file(broken), "ASCII STL does not parse"));
  // A binary file cut short: its size contradicts its triangle count, and it is no text.
  const std::string whole = temp_path("whole.stl"), cut = temp_path("truncated.stl");
  test::write_binary_stl(whole, test::icosphere(10, 1));
  std::filesystem::copy_file(whole, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, std::filesystem::file_size(whole) - 20);
  const std::string why = refusal_of_file(cut);
  EXPECT_TRUE(says(why, "neither an ASCII STL") && says(why, "declares 80 triangles")) << why;
}
