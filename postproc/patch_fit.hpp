#pragma once
// One patch's least-squares polynomial of the superconvergent patch recoveries
// (patch_recovery2d.hpp, patch_recovery3d.hpp): a vector field of dimension Dim fitted, in
// Dim variables, by a polynomial of degree <= 2 about a patch's vertex.
//
// Weighted least squares (weights: quadrature weight x element measure, so that the fit is
// the L2 projection on the patch and small elements do not count more than large ones), on
// coordinates scaled by the patch's radius (normal equations of order one). Falls back to
// lower degrees when the points do not determine the polynomial (a pivot below 1e-10 of the
// largest: points on a plane or a line, as in a patch of one flat layer).
#include <algorithm>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace magfem {

template <int Dim> struct PatchFit {
  using Point = Eigen::Matrix<double, Dim, 1>;
  // Terms of the full quadratic: 1, the Dim variables, their squares, their products.
  static constexpr int max_terms = 1 + Dim + Dim * (Dim + 1) / 2;
  using Basis = Eigen::Matrix<double, max_terms, 1>;
  using Coefficients = Eigen::Matrix<double, max_terms, Dim>;

  // A sample of the field: value g at point x with weight w.
  struct Sample {
    Point x, g;
    double w = 0;
  };

  Point center = Point::Zero();
  double scale = 1;
  int degree = 0;
  Coefficients c = Coefficients::Zero();

  static constexpr int n_terms(int degree) {
    return degree == 0 ? 1 : degree == 1 ? 1 + Dim : max_terms;
  }

  // Monomials of degree <= 2 in xi, ordered by degree (unused entries zero): 1; xi_i;
  // xi_i^2; xi_i xi_j for i < j.
  static Basis monomials(const Point& xi, int degree) {
    Basis m = Basis::Zero();
    m[0] = 1;
    if (degree >= 1)
      m.template segment<Dim>(1) = xi;
    if (degree >= 2) {
      int k = 1 + Dim;
      for (int i = 0; i < Dim; ++i)
        m[k++] = xi[i] * xi[i];
      for (int i = 0; i < Dim; ++i)
        for (int j = i + 1; j < Dim; ++j)
          m[k++] = xi[i] * xi[j];
    }
    return m;
  }

  Point at(const Point& x) const { return c.transpose() * monomials((x - center) / scale, degree); }

  // The fit of `samples` about `center` at `degree` (or the highest lower degree they
  // determine).
  static PatchFit fit(const std::vector<Sample>& samples, const Point& center, int degree) {
    PatchFit f;
    f.center = center;
    double r = 0;
    for (const auto& s : samples)
      r = std::max(r, (s.x - center).norm());
    f.scale = r > 0 ? r : 1;
    // Fixed-size normal equations of the full quadratic basis (hundreds of samples per
    // patch, tens of thousands of patches: no heap per sample); a lower degree solves the
    // leading block (the basis is ordered by degree).
    Eigen::Matrix<double, max_terms, max_terms> a =
        Eigen::Matrix<double, max_terms, max_terms>::Zero();
    Coefficients b = Coefficients::Zero();
    for (const auto& s : samples) {
      const Basis m = monomials((s.x - center) / f.scale, degree);
      a.template selfadjointView<Eigen::Lower>().rankUpdate(m, s.w);
      b.noalias() += s.w * m * s.g.transpose();
    }
    a.template triangularView<Eigen::StrictlyUpper>() = a.transpose();
    for (; degree >= 0; --degree) {
      const int n = n_terms(degree);
      const Eigen::LDLT<Eigen::MatrixXd> ldlt(a.topLeftCorner(n, n));
      const Eigen::VectorXd d = ldlt.vectorD();
      if (ldlt.info() != Eigen::Success || d.minCoeff() <= 1e-10 * d.maxCoeff())
        continue;
      f.degree = degree;
      f.c.topRows(n) = ldlt.solve(b.topRows(n));
      return f;
    }
    return f; // no samples: zero (cannot happen for a slot, which has an element)
  }
};

} // namespace magfem
