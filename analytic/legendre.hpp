#pragma once
// Fully normalized associated Legendre functions for spherical harmonic expansions of any
// degree, and Gauss-Legendre rules for the quadratures that produce the coefficients.
//
// Normalization (the thesis's S_n^m P_n^m, eqs. 3.86-3.89, without the Condon-Shortley phase):
//   Pbar_nm(cos t) = sqrt((2n+1)/(4 pi) (n-m)!/(n+m)!) P_n^m(cos t),  0 <= m <= n,
// so that Pbar_nm(cos t) e^{i m phi} is orthonormal on the unit sphere, i.e.
//   integral_0^pi Pbar_nm^2 sin t dt = 1 / (2 pi).
// The values come from the standard three-term recurrences in n of the normalized functions
// (no factorials). The sectoral seeds Pbar_mm ~ sin^m t underflow for large m near the poles;
// they are carried with an extended exponent so that the columns are exact at any degree
// (values below ~1e-270 are returned as 0, their contribution to any sum is below round-off).
#include <cstddef>
#include <vector>

#include "core/gauss_legendre.hpp"

namespace magfem {

// Storage of a triangle 0 <= m <= n <= n_max column by column (m-major): the entries of one
// order m are contiguous in n, which is the order the recurrences produce them.
class TriangularIndex {
public:
  explicit TriangularIndex(int n_max = 0);

  int n_max() const { return n_max_; }
  std::size_t size() const { return offsets_.back(); }
  // Index of (n = m, m): the column of order m starts here and holds n = m..n_max.
  std::size_t column_start(int m) const { return offsets_[static_cast<std::size_t>(m)]; }
  std::size_t operator()(int n, int m) const {
    return column_start(m) + static_cast<std::size_t>(n - m);
  }

private:
  int n_max_;
  std::vector<std::size_t> offsets_; // n_max + 2 entries, the last one is the size
};

// Values at one polar angle theta, laid out by a TriangularIndex.
struct LegendreValues {
  std::vector<double> p;  // Pbar_nm(cos theta)
  std::vector<double> dp; // d Pbar_nm / d theta
  // Pbar_nm / sin(theta) for m >= 1 (finite at the poles, where only m = 1 is non-zero);
  // 0 for m = 0. This is what the phi-derivative of a harmonic needs: m Pbar_nm / sin(theta).
  std::vector<double> p_over_sin;
};

class LegendreColumn;

class NormalizedLegendre {
public:
  explicit NormalizedLegendre(int n_max);

  int n_max() const { return index_.n_max(); }
  const TriangularIndex& index() const { return index_; }

  // All (n, m) at polar angle theta in [0, pi]; `out` is resized as needed (reuse it to
  // avoid allocations in loops).
  void evaluate(double theta, LegendreValues& out) const;
  LegendreValues evaluate(double theta) const;

private:
  friend class LegendreColumn;
  // Column m >= 1 from the (extended-range) seed Q_mm = seed * 2^seed_exp.
  void fill_order(int m, double x, double u, double seed, int seed_exp, double* p, double* dp,
                  double* q) const;
  void fill_order0(double x, double u, double* p, double* dp, double* q) const;

  TriangularIndex index_;
  std::vector<double> a_; // Pbar_nm = a x Pbar_{n-1,m} - b Pbar_{n-2,m}
  std::vector<double> b_;
  std::vector<double> d_;      // dPbar_nm/dt = n x Q_nm - d Q_{n-1,m}, Q = Pbar / sin t
  std::vector<double> sector_; // Pbar_mm = sector_[m] sin t Pbar_{m-1,m-1}
};

// The columns of one polar angle, produced one order at a time (m = 0, 1, ..., n_max) with
// O(1) state: loops that run over many angles per order keep one LegendreColumn per angle
// and never store the triangle.
class LegendreColumn {
public:
  LegendreColumn(const NormalizedLegendre& legendre, double theta);

  int order() const { return m_; } // the order the next fill() or skip() produces
  // Writes p[j] = Pbar_nm, dp[j] = dPbar_nm/dtheta, q[j] = Pbar_nm / sin(theta) (0 for m = 0)
  // for n = m + j, j = 0..n_max - m, with m = order(); then advances to m + 1.
  void fill(double* p, double* dp, double* q);
  void skip(); // advances without computing the column

private:
  const NormalizedLegendre* legendre_;
  double x_, u_;
  int m_ = 0;
  double seed_;      // Q_mm of the current order m >= 1 (mantissa)
  int seed_exp_ = 0; // and its binary exponent
};

} // namespace magfem
