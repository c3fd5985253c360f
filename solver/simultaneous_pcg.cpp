#include "solver/simultaneous_pcg.hpp"

#include <cmath>
#include <limits>

#include "core/progress.hpp"

namespace magfem {
namespace {

// Every vector operation runs row by row over the block: a row's m values are contiguous, so
// the block is read once, where a column at a time would read it m times.
Eigen::RowVectorXd column_dots(const ColumnBlock& u, const ColumnBlock& v) {
  Eigen::RowVectorXd s = Eigen::RowVectorXd::Zero(u.cols());
  for (Eigen::Index i = 0; i < u.rows(); ++i)
    s += u.row(i).cwiseProduct(v.row(i));
  return s;
}

// The columns `cols` of `from`, side by side; and back.
ColumnBlock gather(const ColumnBlock& from, const std::vector<int>& cols) {
  return from(Eigen::all, cols);
}
void scatter(const ColumnBlock& from, const std::vector<int>& cols, ColumnBlock& to) {
  to.setZero();
  to(Eigen::all, cols) = from;
}

} // namespace

std::vector<KrylovOutcome> simultaneous_pcg(const BlockOperator& a, const BlockOperator& m,
                                            const ColumnBlock& b, ColumnBlock& x, double tol,
                                            int max_iterations, Progress* progress,
                                            const char* progress_name) {
  const Eigen::Index n = b.rows(), n_rhs = b.cols();
  std::vector<KrylovOutcome> out(static_cast<std::size_t>(n_rhs));
  x = ColumnBlock::Zero(n, n_rhs);
  const Eigen::RowVectorXd b_norm2 = column_dots(b, b);
  Eigen::RowVectorXd threshold(n_rhs);
  std::vector<int> active;
  for (Eigen::Index j = 0; j < n_rhs; ++j) {
    threshold[j] = std::max(tol * tol * b_norm2[j], (std::numeric_limits<double>::min)());
    if (b_norm2[j] == 0) {
      out[j].converged = true;
      out[j].reason = "zero right-hand side";
    } else {
      out[j].reason = "DIVERGED_ITS";
      active.push_back(static_cast<int>(j));
    }
  }
  // Full-width blocks; a finished column keeps its x and gets zero steps from then on. The
  // operators see the active columns only.
  auto apply = [&](const BlockOperator& op, const ColumnBlock& in, ColumnBlock& result) {
    if (static_cast<Eigen::Index>(active.size()) == n_rhs) {
      op(in, result);
      return;
    }
    ColumnBlock part(n, static_cast<Eigen::Index>(active.size()));
    op(gather(in, active), part);
    scatter(part, active, result);
  };
  ColumnBlock r = b, z(n, n_rhs), p(n, n_rhs), ap(n, n_rhs);
  apply(m, r, z);
  p = z;
  Eigen::RowVectorXd rz = column_dots(r, z), r_norm2 = b_norm2;
  for (int it = 1; it <= max_iterations && !active.empty(); ++it) {
    apply(a, p, ap);
    const Eigen::RowVectorXd pap = column_dots(p, ap);
    Eigen::RowVectorXd alpha = Eigen::RowVectorXd::Zero(n_rhs);
    std::vector<int> moving;
    for (int j : active) {
      if (!(pap[j] > 0) || !(rz[j] > 0)) {
        out[j].reason = std::isfinite(pap[j]) && std::isfinite(rz[j]) ? "DIVERGED_INDEFINITE"
                                                                      : "DIVERGED_NANORINF";
        continue;
      }
      alpha[j] = rz[j] / pap[j];
      out[j].iterations = it;
      moving.push_back(j);
    }
    x.noalias() += p * alpha.asDiagonal();
    r.noalias() -= ap * alpha.asDiagonal();
    const Eigen::RowVectorXd r2 = column_dots(r, r);
    std::vector<int> still;
    double worst = 0;
    for (int j : moving) {
      r_norm2[j] = r2[j];
      if (r_norm2[j] < threshold[j]) {
        out[j].converged = true;
        out[j].reason = "CONVERGED_RTOL";
      } else {
        still.push_back(j);
        worst = std::max(worst, std::sqrt(r_norm2[j] / b_norm2[j]));
      }
    }
    active = std::move(still);
    if (active.empty())
      break;
    if (progress)
      progress->iteration(progress_name, it, worst);
    apply(m, r, z);
    const Eigen::RowVectorXd rz_new = column_dots(r, z);
    Eigen::RowVectorXd beta = Eigen::RowVectorXd::Zero(n_rhs);
    for (int j : active)
      beta[j] = rz_new[j] / rz[j];
    rz = rz_new;
    p = z + p * beta.asDiagonal();
  }
  for (Eigen::Index j = 0; j < n_rhs; ++j)
    if (b_norm2[j] > 0)
      out[j].relative_residual = std::sqrt(r_norm2[j] / b_norm2[j]);
  return out;
}

} // namespace magfem
