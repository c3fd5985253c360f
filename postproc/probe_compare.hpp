#pragma once
// Point-by-point comparison of two probe CSVs of the same probe (e.g. FE against the charge
// model). Per field component it reports both measures the thesis work needs:
//   eq. 3.117 discrepancy  (rms(ref) - rms(test)) / rms(ref)   -- compares rms values only
//   pointwise rms error    rms(test - ref) / rms(ref)           -- sees every point
// The first can be small while the second is large (errors of both signs cancel), so both
// are always printed.
#include <istream>
#include <string>
#include <vector>

#include "postproc/probe_table.hpp"

namespace magfem {

// Reads a probe CSV; a malformed file is an InputError naming file, line and column.
ProbeTable read_probe_csv(const std::string& path);
// The same from a stream; `name` stands for the file in messages (tests, fuzzing).
ProbeTable read_probe_csv(std::istream& in, const std::string& name);

struct ComponentComparison {
  std::string component;
  double rms_reference = 0, rms_test = 0;
  double discrepancy_3117 = 0;   // fraction, signed
  double pointwise_rms = 0;      // fraction
  double max_abs_difference = 0; // tesla
  double rms_difference = 0;     // tesla: rms(test - ref), defined whatever the reference
  // False when the reference component is zero, or below 1e-9 of the largest component's
  // rms (B_phi of an axisymmetric field: round-off): the two fractions would divide by it,
  // so they are 0 and only the absolute differences mean anything.
  bool relative_defined = true;
};

// Throws std::invalid_argument if the tables do not sample the same points.
std::vector<ComponentComparison> compare_probes(const ProbeTable& reference,
                                                const ProbeTable& test);

} // namespace magfem
