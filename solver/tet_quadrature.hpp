#pragma once
// Symmetric quadrature rules on the reference tetrahedron in barycentric coordinates, all
// weights positive; weights sum to 1 (multiply by the tet volume).
#include <array>
#include <vector>

namespace magfem {

struct TetQuadPoint {
  std::array<double, 4> bary;
  double weight;
};

namespace detail {
// The 4 permutations of (a, a, a, 1 - 3a).
inline void add_orbit4(std::vector<TetQuadPoint>& rule, double a, double w) {
  const double b = 1 - 3 * a;
  for (int k = 0; k < 4; ++k) {
    TetQuadPoint q{{a, a, a, a}, w};
    q.bary[k] = b;
    rule.push_back(q);
  }
}
// The 6 permutations of (a, a, 1/2 - a, 1/2 - a).
inline void add_orbit6(std::vector<TetQuadPoint>& rule, double a, double w) {
  const double b = 0.5 - a;
  static constexpr std::array<std::array<int, 2>, 6> pairs = {
      {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
  for (const auto& p : pairs) {
    TetQuadPoint q{{b, b, b, b}, w};
    q.bary[p[0]] = a;
    q.bary[p[1]] = a;
    rule.push_back(q);
  }
}
} // namespace detail

// Exact for polynomials of degree <= `degree`: 1 (centroid), 2 (4 points), 5 (14 points,
// Walkington's positive rule; used for every request above 2).
inline const std::vector<TetQuadPoint>& tet_rule(int degree) {
  static const std::vector<TetQuadPoint> d1 = {{{0.25, 0.25, 0.25, 0.25}, 1.0}};
  static const std::vector<TetQuadPoint> d2 = [] {
    std::vector<TetQuadPoint> r;
    detail::add_orbit4(r, 0.1381966011250105151795413, 0.25);
    return r;
  }();
  static const std::vector<TetQuadPoint> d5 = [] {
    std::vector<TetQuadPoint> r;
    detail::add_orbit4(r, 0.0927352503108912264, 6 * 0.0122488405193936582);
    detail::add_orbit4(r, 0.3108859192633006097, 6 * 0.0187813209530026417);
    detail::add_orbit6(r, 0.0455037041256496494, 6 * 0.0070910034628469110);
    return r;
  }();
  if (degree <= 1)
    return d1;
  if (degree <= 2)
    return d2;
  return d5;
}

} // namespace magfem
