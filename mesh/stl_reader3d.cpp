#include "mesh/stl_reader3d.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL/STL_reader.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include "mesh/mesh_error.hpp"
#include "mesh/surface_index3d.hpp"

namespace magfem {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;
using Soup = std::vector<std::vector<std::size_t>>;

// Bytes of a binary STL: an 80-byte header, a 32-bit triangle count, 50 bytes per triangle.
constexpr std::uintmax_t binary_header = 84, binary_record = 50;

class Failure {
public:
  explicit Failure(std::string path) : path_(std::move(path)) {}
  [[noreturn]] void operator()(const std::string& reason) const {
    throw MeshError("", "file", path_ + ": " + reason);
  }
  // A location in the file's own coordinates (units), as the CAD system shows it.
  std::string at(const Point& p) const {
    char text[120];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
    return text;
  }

private:
  std::string path_;
};

enum class Format { ascii, binary };

// Which of the two formats the bytes are. A binary file may begin with "solid" too (several
// CAD exporters write it into the header), so the size rule decides first: a binary file is
// exactly 84 + 50 N bytes for the N its header declares.
Format classify(const std::string& path, const Failure& fail) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in)
    fail("cannot read the file");
  if (size == 0)
    fail("the file is empty");
  std::string head(binary_header, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::uint32_t n = 0;
  if (head.size() == binary_header) {
    std::memcpy(&n, head.data() + 80, sizeof n);
    if (size == binary_header + binary_record * n)
      return Format::binary;
  }
  std::size_t first = 0;
  while (first < head.size() && std::isspace(static_cast<unsigned char>(head[first])))
    ++first;
  if (head.compare(first, 5, "solid") == 0)
    return Format::ascii;
  std::ostringstream why;
  why << "neither an ASCII STL (it does not begin with 'solid') nor a binary STL (";
  if (head.size() < binary_header)
    why << "shorter than the 84-byte header";
  else
    why << "its header declares " << n << " triangles, " << binary_header + binary_record * n
        << " bytes, but the file has " << size << "; a truncated file or one copied in text mode?";
  why << ")";
  fail(why.str());
}

// STL stores single-precision coordinates (the binary format is IEEE float32): ASCII values
// are rounded to float as well, so that the same surface written either way is the same part,
// bit for bit. Coincident points are merged after the rounding.
void read_soup(const std::string& path, Format format, const Failure& fail,
               std::vector<Point>& points, Soup& soup) {
  std::ifstream in(path, std::ios::binary);
  std::vector<Point> raw;
  std::vector<std::array<std::size_t, 3>> tris;
  // CGAL's parsers for the one format the file is. Its read_STL guesses the format by the
  // first word: a binary file whose header begins with "solid" goes to the ASCII parser first,
  // whose partial output stays in the ranges when it fails, and a broken ASCII file then
  // "succeeds" as an empty binary one.
  if (format == Format::binary && !CGAL::IO::internal::parse_binary_STL(in, raw, tris))
    fail("the binary STL ends early");
  if (format == Format::ascii) {
    std::string word;
    in >> word; // "solid": the parser expects it read
    if (!CGAL::IO::internal::parse_ASCII_STL(in, raw, tris))
      fail("the ASCII STL does not parse (a facet without 3 vertices, a bad number or a missing "
           "'endsolid'?)");
  }
  if (tris.empty())
    fail("the file contains no triangles");
  std::map<std::array<float, 3>, std::size_t> id;
  std::vector<std::size_t> new_id(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const std::array<float, 3> x{static_cast<float>(raw[i].x()), static_cast<float>(raw[i].y()),
                                 static_cast<float>(raw[i].z())};
    const auto [it, added] = id.emplace(x, points.size());
    if (added)
      points.emplace_back(x[0], x[1], x[2]);
    new_id[i] = it->second;
  }
  for (const auto& t : tris)
    soup.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]]});
}

void check_triangles(const std::vector<Point>& points, const Soup& soup, const Failure& fail) {
  for (std::size_t t = 0; t < soup.size(); ++t) {
    const Point &a = points[soup[t][0]], &b = points[soup[t][1]], &c = points[soup[t][2]];
    // Collinear to single precision: the height is below 1e-6 of the longest edge.
    const double longest2 = std::max(
        {CGAL::squared_distance(a, b), CGAL::squared_distance(b, c), CGAL::squared_distance(c, a)});
    const double area2 = CGAL::squared_area(a, b, c);
    if (soup[t][0] == soup[t][1] || soup[t][1] == soup[t][2] || soup[t][0] == soup[t][2] ||
        4 * area2 <= 1e-12 * longest2 * longest2)
      fail("triangle " + std::to_string(t + 1) + " at " + fail.at(a) +
           " has no area (coincident or collinear corners)");
  }
}

// Every edge must bound exactly two triangles: one is a hole's rim, three or more a fin or
// two bodies sharing an edge.
void check_edges(const std::vector<Point>& points, const Soup& soup, const Failure& fail) {
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (const auto& t : soup)
    for (int k = 0; k < 3; ++k)
      ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  std::size_t n_open = 0;
  const std::pair<std::size_t, std::size_t>* first_open = nullptr;
  for (const auto& [edge, n] : uses) {
    if (n > 2)
      fail("not a manifold: the edge from " + fail.at(points[edge.first]) + " to " +
           fail.at(points[edge.second]) + " is shared by " + std::to_string(n) + " triangles");
    if (n == 1 && n_open++ == 0)
      first_open = &edge;
  }
  if (n_open > 0)
    fail("the surface is not closed: " + std::to_string(n_open) +
         " edges belong to one triangle only (a hole; the first from " +
         fail.at(points[first_open->first]) + " to " + fail.at(points[first_open->second]) +
         "); export the part as a closed solid");
}

SurfaceMesh to_mesh(std::vector<Point>& points, Soup& soup, const Failure& fail) {
  const std::size_t n_points = points.size();
  if (!PMP::orient_polygon_soup(points, soup))
    fail("not a manifold: separate sheets of the surface meet at the point " +
         fail.at(points[n_points]) + " (two bodies touching at a corner?)");
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, soup, mesh);
  auto component = mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc").first;
  const std::size_t n_pieces = PMP::connected_components(mesh, component);
  if (n_pieces != 1)
    fail("the surface has " + std::to_string(n_pieces) +
         " separate pieces: export each body to its own file (one part per region)");
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> crossing;
  PMP::self_intersections(mesh, std::back_inserter(crossing));
  if (!crossing.empty()) {
    const auto h = mesh.halfedge(crossing.front().first);
    fail("the surface intersects itself (" + std::to_string(crossing.size()) +
         " pairs of triangles; the first near " + fail.at(mesh.point(mesh.target(h))) + ")");
  }
  if (!PMP::is_outward_oriented(mesh))
    PMP::reverse_face_orientations(mesh);
  return mesh;
}

// A point just inside the surface, off the centroid of its largest triangle by a thousandth of
// that triangle's shortest edge: the seed of the part's region in TetGen.
Vec3 inside_point(const TriangleSurface& s, const SurfaceIndex3D& index, const Failure& fail) {
  std::vector<std::pair<double, std::size_t>> by_area;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tr = s.triangles[t];
    const Vec3 n = (s.points[tr[1]] - s.points[tr[0]]).cross(s.points[tr[2]] - s.points[tr[0]]);
    by_area.emplace_back(-n.norm(), t);
  }
  std::sort(by_area.begin(), by_area.end());
  for (std::size_t i = 0; i < std::min<std::size_t>(by_area.size(), 20); ++i) {
    const auto& tr = s.triangles[by_area[i].second];
    const Vec3 a = s.points[tr[0]], b = s.points[tr[1]], c = s.points[tr[2]];
    const double eps = 1e-3 * std::min({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const Vec3 x = (a + b + c) / 3 - eps * (b - a).cross(c - a).normalized();
    if (index.contains(x, -0.5 * eps))
      return x;
  }
  fail("no point just inside the surface was found (is the part thinner than a thousandth of "
       "its triangles?)");
}

} // namespace

TriangleSurface read_stl_surface(const std::string& path, double unit_m) {
  const Failure fail(path);
  const Format format = classify(path, fail);
  std::vector<Point> points;
  Soup soup;
  read_soup(path, format, fail, points, soup);
  check_triangles(points, soup, fail);
  check_edges(points, soup, fail);
  const SurfaceMesh mesh = to_mesh(points, soup, fail);

  TriangleSurface s;
  s.file = path;
  std::map<SurfaceMesh::Vertex_index, int> id;
  for (const auto v : mesh.vertices()) {
    id[v] = static_cast<int>(s.points.size());
    const Point& p = mesh.point(v);
    s.points.push_back(unit_m * Vec3(p.x(), p.y(), p.z()));
  }
  for (const auto f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[k++] = id[v];
    s.triangles.push_back(t);
  }
  auto index = std::make_shared<const SurfaceIndex3D>(s.points, s.triangles);
  s.inside_point = inside_point(s, *index, fail);
  s.index = std::move(index);
  return s;
}

} // namespace magfem
