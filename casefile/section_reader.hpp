#pragma once
// The `sections:` section of a case file (see docs/case_format.md): plane rectangles and
// disks (3D, postproc/section_flux3d.hpp) and lines (2D and axisymmetric,
// postproc/section_flux2d.hpp) through which the flux of B is integrated.
#include "casefile/case_spec.hpp"
#include "core/yaml_node.hpp"

namespace magfem {

// Appends the validated sections to c.sections; c's dimension, unit and outer boundary must
// already be read (a section must lie inside the domain).
void read_sections(const YamlNode& list, CaseSpec& c);

} // namespace magfem
