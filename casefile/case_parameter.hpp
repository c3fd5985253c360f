#pragma once
// One resolved case-file parameter, and command-line overrides of parameter values (kept
// apart from case_parameters.hpp so that CaseSpec does not pull in the YAML parser).
#include <map>
#include <string>

namespace magfem {

// Values given on the command line (`--param NAME=VALUE`), in the parameter's own unit.
using ParameterOverrides = std::map<std::string, double>;

struct CaseParameter {
  std::string name;
  double value = 0; // in the case's units (lengths in `unit`, angles in degrees), overrides applied
  std::string unit; // as declared ("" if none)
  int line = 0;
};

} // namespace magfem
