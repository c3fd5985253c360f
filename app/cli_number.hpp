#pragma once
// Numbers on the command line: the whole text must be one finite number, else an InputError
// naming the option (the command line has no file or line).
#include <string>

namespace magfem {

double parse_cli_number(const std::string& option, const std::string& text);

// The FE mesh options shared by the commands that solve: --mesh-scale (positive) and
// --order (exactly 1 or 2).
double parse_cli_mesh_scale(const std::string& text);
int parse_cli_order(const std::string& text);

} // namespace magfem
