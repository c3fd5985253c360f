#pragma once
// Quadrature for the source integrals of coil fields: the Biot-Savart kernel of a filament,
// integrated over a bundle's cross-section, is analytic except near the field point, where it
// behaves like 1/d (d = distance in the cross-section plane). Far from the bundle a tensor
// Gauss-Legendre rule whose order follows the distance suffices; near or inside it the
// cross-section is split at the field point and each piece that touches it is integrated in
// Duffy coordinates (the 1/d singularity cancels against the Jacobian), with geometric
// panels towards the point to resolve what is left (the scale of a point just outside, the
// end of a finite bundle). Rules live on parameter rectangles; the callers map them.
#include <vector>

#include "core/gauss_legendre.hpp"

namespace magfem {

// Gauss-Legendre rules on [-1, 1], built once per process (thread-safe) for 1 <= n <= 64;
// larger n are clamped to 64.
inline constexpr int max_cached_gauss_order = 64;
const QuadratureRule& cached_gauss(int n);

// Points with which Gauss-Legendre integrates, to relative error ~`tol`, a function on the
// interval [mid - half, mid + half] that is analytic except for singularities at re +- i im,
// times a polynomial factor of degree `poly_degree` vanishing at `poly_root` (the a^2 of a loop
// of radius a, say). The error falls like rho^-2n, rho the parameter of a Bernstein ellipse
// within the one through the singularity, weighted by the integrand's growth on it. At least
// n_min; n_max + 1 means "more than n_max" (the singularity is too close for a plain rule).
int gauss_order_for(double mid, double half, double re, double im, double tol, int n_min, int n_max,
                    int poly_degree = 0, double poly_root = 0.0);

// Points with which Gauss-Legendre integrates, to relative error ~`tol`, an entire factor of
// exponential type `type` (cos(type x), sin^2 x has type 2) over an interval of half-length
// `half`: the error of such a factor is ~ (type half)^2n / (2n)! (its Legendre coefficients).
// At least n_min; n_max + 1 if n_max points do not suffice.
int gauss_order_entire(double type, double half, double tol, int n_min, int n_max);

struct Node1 {
  double x, w;
};
struct Node2 {
  double u, v, w;
};

// Appends a rule for [a, b] whose integrand is (nearly) singular at x_s (clamped to [a, b]):
// the interval is split at x_s and each side is cut into geometric panels (ratio `ratio`)
// shrinking towards x_s until the innermost panel is no longer than `width` (the distance of
// the singularity from the real axis, or the smallest scale of the integrand; 0 means the
// integrand is regular at x_s and only `min_panels` panels are used). `n` points per panel.
// With `square_innermost` the innermost panel is mapped by x = x_s + l sigma^2, for
// integrands with x log x terms at x_s (what a logarithmic kernel leaves after Duffy).
void append_graded_rule(double a, double b, double x_s, double width, int n, double ratio,
                        int min_panels, bool square_innermost, std::vector<Node1>& out);

struct ParamRect {
  double u0, u1, v0, v1;
};

// How the near rule adapts to the field point.
struct NearPoint {
  double u, v;   // parameter coordinates of the field point (clamped to the rectangle here)
  double su, sv; // physical length per unit of u and of v there (the map's metric)
  double width;  // physical scale the Duffy radial panels must resolve (0: none)
  bool singular; // the point lies in the bundle: 1/d and log d at the corner itself, the
                 // innermost radial panel is then mapped by s = sigma^2
  int n;         // Gauss points per panel and direction
};

// Appends the split + Duffy rule on `rect` for a kernel singular like 1/d at `p` (see the file
// comment). Weights are parameter-area weights du dv; the caller multiplies by its own
// Jacobian. The sum of the weights is the rectangle's area to round-off.
void append_near_rule(const ParamRect& rect, const NearPoint& p, std::vector<Node2>& out);

} // namespace magfem
