#pragma once
// Closed triangulated surfaces for the STL tests: an icosphere (outward triangles) and
// writers of ASCII and binary STL files with the same single-precision coordinates.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace magfem::test {

struct TriSurface {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles; // counter-clockwise seen from outside
};

// The icosahedron's triangles split `levels` times into four, new points pushed onto the
// sphere of `radius`: 20 * 4^levels triangles.
inline TriSurface icosphere(double radius, int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriSurface s;
  for (const auto& p : std::vector<Eigen::Vector3d>{{-1, t, 0},
                                                    {1, t, 0},
                                                    {-1, -t, 0},
                                                    {1, -t, 0},
                                                    {0, -1, t},
                                                    {0, 1, t},
                                                    {0, -1, -t},
                                                    {0, 1, -t},
                                                    {t, 0, -1},
                                                    {t, 0, 1},
                                                    {-t, 0, -1},
                                                    {-t, 0, 1}})
    s.points.push_back(p.normalized());
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      s.points.push_back((s.points[a] + s.points[b]).normalized());
      return mid[key] = static_cast<int>(s.points.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& f : s.triangles) {
      const int a = middle(f[0], f[1]), b = middle(f[1], f[2]), c = middle(f[2], f[0]);
      next.insert(next.end(), {{f[0], a, c}, {f[1], b, a}, {f[2], c, b}, {a, b, c}});
    }
    s.triangles = next;
  }
  for (auto& p : s.points)
    p *= radius;
  return s;
}

inline void write_ascii_stl(const std::string& path, const TriSurface& s) {
  std::ofstream out(path);
  out << "solid test\n";
  char line[200];
  for (const auto& t : s.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (int k : t) {
      // Single precision printed exactly enough to read back the same float.
      std::snprintf(line, sizeof line, "   vertex %.9g %.9g %.9g\n", double(float(s.points[k].x())),
                    double(float(s.points[k].y())), double(float(s.points[k].z())));
      out << line;
    }
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

// header: the 80-byte header's text (CAD exporters often begin it with "solid").
inline void write_binary_stl(const std::string& path, const TriSurface& s,
                             const std::string& header = "binary test surface") {
  std::ofstream out(path, std::ios::binary);
  std::string h = header;
  h.resize(80, ' ');
  out.write(h.data(), 80);
  const std::uint32_t n = static_cast<std::uint32_t>(s.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : s.triangles) {
    float v[12] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        v[3 + 3 * k + c] = static_cast<float>(s.points[t[k]][c]);
    out.write(reinterpret_cast<const char*>(v), sizeof v);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

} // namespace magfem::test
