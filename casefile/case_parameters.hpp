#pragma once
// The `parameters:` section of a case file and the substitution of `${expression}` anywhere
// else in the file, before anything is read (so every reader sees plain numbers and keeps its
// own validation and units):
//
//   parameters:
//     R_in: {value: 29, unit: mm}
//     gap: 1                      # a plain number: the case's units
//     R_out: ${R_in + 14}         # an expression of other parameters
//   regions:
//     - {name: outer, ..., r_inner: "${R_in + gap}", r_outer: ${R_out}}
//
// Units: a literal value with a length unit (m, cm, mm, um) is converted to the case's
// `unit`, one in rad to degrees (case angles are degrees); other units are labels. Names
// inside expressions stand for these converted values, and an expression's value is in the
// case's units. A scalar that is exactly `${...}` becomes the number; `${...}` inside longer
// text (a title) is replaced by the number's shortest form. In YAML flow collections
// (`[..]`, `{..}`) the braces of `${..}` are flow indicators, so quote_expressions() quotes
// every `${..}` that stands alone as a value before the text is parsed.
//
// Errors (InputError naming file, line and dotted field): an undefined name, a cycle between
// parameters, a syntax error or a non-finite result, an override of an unknown parameter.
#include <string>
#include <vector>

#include "casefile/case_parameter.hpp"
#include "core/yaml_node.hpp"

namespace magfem {

// The case-file text with each unquoted `${..}` that is a whole value (after `:`, `,`, `[`,
// `{`, `-` or at the start of a line; before `,`, `]`, `}`, a comment or the end of the line)
// put in double quotes. Lines are kept, so parser lines stay the file's lines.
std::string quote_expressions(const std::string& text);

// Resolves root's `parameters:` (if any) with the overrides, and rewrites every other scalar
// of the tree that contains `${` in place. `length_unit` is the case's metres per unit.
std::vector<CaseParameter>
apply_parameters(const YamlNode& root, const ParameterOverrides& overrides, double length_unit);

} // namespace magfem
