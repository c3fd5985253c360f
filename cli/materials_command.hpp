#pragma once
// `magfem materials`: the bundled library's entries, one a line; `magfem materials --export
// NAME` writes a soft entry's B-H table to stdout in the format `bh_file:` reads
// (materials/bh_table_file.hpp), so a user can start a curve of their own from it.
#include <string>
#include <vector>

#include "core/option_table.hpp"

namespace magfem {

struct MaterialsOptions {
  std::vector<std::string> export_names; // --export NAME (one)
};
const OptionTable<MaterialsOptions>& materials_option_table();

// Exit code 0; an unknown option, an unknown name or an entry without a curve is an
// InputError naming the option.
int run_materials_command(const std::vector<std::string>& args);

} // namespace magfem
