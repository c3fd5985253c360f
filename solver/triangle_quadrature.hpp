#pragma once
// Symmetric quadrature rules on the reference triangle in barycentric coordinates; weights sum
// to 1 (multiply by the triangle area).
#include <array>
#include <vector>

namespace magfem {

struct TriangleQuadPoint {
  std::array<double, 3> bary;
  double weight;
};

// Exact for polynomials of degree <= `degree` (1, 2 or 4 supported; others round up).
inline const std::vector<TriangleQuadPoint>& triangle_rule(int degree) {
  static const std::vector<TriangleQuadPoint> d1 = {{{1.0 / 3, 1.0 / 3, 1.0 / 3}, 1.0}};
  static const std::vector<TriangleQuadPoint> d2 = {{{2.0 / 3, 1.0 / 6, 1.0 / 6}, 1.0 / 3},
                                                    {{1.0 / 6, 2.0 / 3, 1.0 / 6}, 1.0 / 3},
                                                    {{1.0 / 6, 1.0 / 6, 2.0 / 3}, 1.0 / 3}};
  // Dunavant (1985), degree 4, 6 points.
  constexpr double a1 = 0.445948490915965, b1 = 0.108103018168070, w1 = 0.223381589678011;
  constexpr double a2 = 0.091576213509771, b2 = 0.816847572980459, w2 = 0.109951743655322;
  static const std::vector<TriangleQuadPoint> d4 = {
      {{b1, a1, a1}, w1}, {{a1, b1, a1}, w1}, {{a1, a1, b1}, w1},
      {{b2, a2, a2}, w2}, {{a2, b2, a2}, w2}, {{a2, a2, b2}, w2}};
  if (degree <= 1) return d1;
  if (degree <= 2) return d2;
  return d4;
}

} // namespace magfem
