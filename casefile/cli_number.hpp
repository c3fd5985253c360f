#pragma once
// Numbers on the command line: the whole text must be one finite number, else an InputError
// naming the option (the command line has no file or line).
#include <string>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_parameter.hpp"

namespace magfem {

double parse_cli_number(const std::string& option, const std::string& text);

// The FE mesh options shared by the commands that solve: --mesh-scale (positive) and
// --order (exactly 1 or 2).
double parse_cli_mesh_scale(const std::string& text);
int parse_cli_order(const std::string& text);

// The adaptive solve's options shared by the commands that solve: --accuracy PCT (0 < PCT <
// 100), --max-passes N (a whole number >= 1), --max-unknowns N (positive), set in `o`
// (`option` names which; an unknown one is a programming error).
void parse_cli_adapt(const std::string& option, const std::string& text, AdaptOverrides& o);
// Unless `allowed` (the command solves something they can refine), an adaptive option given
// in `o` is an InputError naming the first one given, with `why`.
void refuse_adapt_options_unless(const AdaptOverrides& o, bool allowed, const std::string& why);

// --param NAME=VALUE: sets parameters[NAME] (the case file's `parameters:`; read_case checks
// that the file declares NAME).
void parse_cli_parameter(const std::string& text, ParameterOverrides& parameters);

} // namespace magfem
