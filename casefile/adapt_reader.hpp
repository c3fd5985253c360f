#pragma once
// The `adapt:` section of a case file (see docs/case_format.md).
#include "casefile/case_spec.hpp"
#include "core/yaml_node.hpp"

namespace magfem {

// Reads and validates c.adapt; c's dimension, forces and probes must already be read (the
// quantities name them).
void read_adapt(const YamlNode& node, CaseSpec& c);

} // namespace magfem
