#pragma once
// The `forces:` section of a case file (see docs/case_format.md).
#include "casefile/case_spec.hpp"
#include "core/yaml_node.hpp"

namespace magfem {

// Appends the validated force requests to c.forces; c's dimension, unit, regions and outer
// boundary must already be read (surfaces must lie inside the domain, regions must exist).
void read_forces(const YamlNode& list, CaseSpec& c);

} // namespace magfem
