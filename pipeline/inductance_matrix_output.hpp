#pragma once
// An inductance matrix as summary.json's "inductance_H" and as the console's rows, written
// once for 3D, axisymmetric and analytic runs.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace magfem {

// {"names": [...], "matrix": [[...]]}, rows and columns in the order of names (H).
nlohmann::ordered_json inductance_matrix_json(const std::vector<std::string>& names,
                                              const Eigen::MatrixXd& l);

// "L (H)   " then one line per row; empty for an empty matrix or one of more than 4 coils
// (summary.json has it whole).
std::string describe_inductance_matrix(const Eigen::MatrixXd& l);

} // namespace magfem
