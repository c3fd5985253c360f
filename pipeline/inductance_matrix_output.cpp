#include "pipeline/inductance_matrix_output.hpp"

#include <cstdio>

namespace magfem {

nlohmann::ordered_json inductance_matrix_json(const std::vector<std::string>& names,
                                              const Eigen::MatrixXd& l) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < l.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < l.cols(); ++k)
      row.push_back(l(i, k));
    rows.push_back(row);
  }
  return {{"names", names}, {"matrix", rows}};
}

std::string describe_inductance_matrix(const Eigen::MatrixXd& l) {
  if (l.size() == 0 || l.rows() > 4)
    return "";
  std::string s;
  char buf[32];
  for (Eigen::Index i = 0; i < l.rows(); ++i) {
    s += i == 0 ? "L (H)   " : "        ";
    for (Eigen::Index k = 0; k < l.cols(); ++k) {
      std::snprintf(buf, sizeof buf, " %12.6g", l(i, k));
      s += buf;
    }
    s += "\n";
  }
  return s;
}

} // namespace magfem
