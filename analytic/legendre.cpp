#include "analytic/legendre.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"

namespace magfem {

TriangularIndex::TriangularIndex(int n_max) : n_max_(n_max) {
  if (n_max < 0) {
    throw std::invalid_argument("TriangularIndex: n_max must be >= 0, got " +
                                std::to_string(n_max));
  }
  offsets_.resize(static_cast<std::size_t>(n_max) + 2);
  offsets_[0] = 0;
  for (int m = 0; m <= n_max; ++m) {
    offsets_[static_cast<std::size_t>(m) + 1] =
        offsets_[static_cast<std::size_t>(m)] + static_cast<std::size_t>(n_max - m + 1);
  }
}

NormalizedLegendre::NormalizedLegendre(int n_max) : index_(n_max) {
  a_.assign(index_.size(), 0.0);
  b_.assign(index_.size(), 0.0);
  d_.assign(index_.size(), 0.0);
  sector_.assign(static_cast<std::size_t>(n_max) + 1, 0.0);
  for (int m = 1; m <= n_max; ++m) {
    sector_[static_cast<std::size_t>(m)] = std::sqrt((2.0 * m + 1.0) / (2.0 * m));
  }
  for (int m = 0; m <= n_max; ++m) {
    for (int n = m; n <= n_max; ++n) {
      const std::size_t k = index_(n, m);
      const double nn = n, mm = m;
      if (n >= m + 2) {
        a_[k] = std::sqrt((2 * nn - 1) * (2 * nn + 1) / ((nn - mm) * (nn + mm)));
        b_[k] = std::sqrt((2 * nn + 1) * (nn + mm - 1) * (nn - mm - 1) /
                          ((2 * nn - 3) * (nn + mm) * (nn - mm)));
      } else if (n == m + 1) {
        a_[k] = std::sqrt(2 * mm + 3);
      }
      if (n > m) {
        d_[k] = std::sqrt((2 * nn + 1) * (nn - mm) * (nn + mm) / (2 * nn - 1));
      }
    }
  }
}

namespace {

// Extended-range number value = mantissa * 2^exponent, exponent a multiple of kStep.
constexpr int kStep = 256;
const double kBig = std::ldexp(1.0, kStep);
const double kSmall = std::ldexp(1.0, -kStep);

} // namespace

void NormalizedLegendre::fill_order(int m, double x, double u, double seed, int seed_exp, double* p,
                                    double* dp, double* q) const {
  // Q_nm = Pbar_nm / sin(t) obeys the same recurrence in n as Pbar_nm, seeded with
  // Q_mm = c_m sin^{m-1} t: nothing is divided by sin t and the poles are regular. While the
  // values are below the double range they are carried as mantissa * 2^e.
  const int nmax = n_max();
  const std::size_t c = index_.column_start(m);
  double q_prev = 0.0; // Q_{n-2,m} (scaled)
  double q_cur = seed; // Q_{n-1,m} (scaled), starts as Q_mm
  int e = seed_exp;
  double out_prev = 0.0; // unscaled Q_{n-1,m}
  for (int n = m; n <= nmax; ++n) {
    const std::size_t j = static_cast<std::size_t>(n - m);
    if (n > m) {
      const double q_next = a_[c + j] * x * q_cur - b_[c + j] * q_prev;
      q_prev = q_cur;
      q_cur = q_next;
      if (e < 0 && std::abs(q_cur) > kBig) {
        q_cur *= kSmall;
        q_prev *= kSmall;
        e += kStep;
      }
    }
    const double qn = e == 0 ? q_cur : std::ldexp(q_cur, e);
    q[j] = qn;
    p[j] = u * qn;
    // sin(t) dP_n^m/dt = n x P_n^m - (n+m) P_{n-1}^m, normalized.
    dp[j] = n * x * qn - d_[c + j] * out_prev;
    out_prev = qn;
  }
}

void NormalizedLegendre::fill_order0(double x, double u, double* p, double* dp, double* q) const {
  // Pbar_n0 by the plain recurrence (values O(1)); dPbar_n0/dt = -sqrt(n(n+1)) Pbar_n1, with
  // Pbar_n1 = sin(t) Q_n1 run alongside.
  const std::size_t c1 = index_.column_start(1);
  double p_prev = 0.0, p_cur = 1.0 / std::sqrt(4.0 * pi);
  double q_prev = 0.0, q_cur = std::sqrt(3.0 / 2.0) / std::sqrt(4.0 * pi); // Q_11
  for (int n = 0; n <= n_max(); ++n) {
    const auto k = static_cast<std::size_t>(n);
    if (n > 0) {
      const double p_next = a_[k] * x * p_cur - b_[k] * p_prev;
      p_prev = p_cur;
      p_cur = p_next;
      if (n > 1) {
        const double q_next = a_[c1 + k - 1] * x * q_cur - b_[c1 + k - 1] * q_prev;
        q_prev = q_cur;
        q_cur = q_next;
      }
      dp[k] = -std::sqrt(static_cast<double>(n) * (n + 1)) * u * q_cur;
    } else {
      dp[k] = 0.0;
    }
    p[k] = p_cur;
    q[k] = 0.0;
  }
}

void NormalizedLegendre::evaluate(double theta, LegendreValues& out) const {
  const std::size_t size = index_.size();
  out.p.resize(size);
  out.dp.resize(size);
  out.p_over_sin.resize(size);
  LegendreColumn column(*this, theta);
  for (int m = 0; m <= n_max(); ++m) {
    const std::size_t c = index_.column_start(m);
    column.fill(&out.p[c], &out.dp[c], &out.p_over_sin[c]);
  }
}

LegendreColumn::LegendreColumn(const NormalizedLegendre& legendre, double theta)
    : legendre_(&legendre), x_(std::cos(theta)), u_(std::abs(std::sin(theta))),
      seed_(std::sqrt(3.0 / 2.0) / std::sqrt(4.0 * pi)) {}

void LegendreColumn::fill(double* p, double* dp, double* q) {
  if (m_ == 0) {
    legendre_->fill_order0(x_, u_, p, dp, q);
  } else {
    legendre_->fill_order(m_, x_, u_, seed_, seed_exp_, p, dp, q);
  }
  skip();
}

void LegendreColumn::skip() {
  ++m_;
  if (m_ >= 2 && m_ <= legendre_->n_max()) {
    seed_ *= legendre_->sector_[static_cast<std::size_t>(m_)] * u_;
    while (seed_ != 0.0 && std::abs(seed_) < kSmall) {
      seed_ *= kBig;
      seed_exp_ -= kStep;
    }
  }
}

LegendreValues NormalizedLegendre::evaluate(double theta) const {
  LegendreValues v;
  evaluate(theta, v);
  return v;
}

} // namespace magfem
