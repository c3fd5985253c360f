#include "cli/materials_command.hpp"

#include <iostream>

#include "core/input_error.hpp"
#include "materials/bh_table_file.hpp"
#include "materials/material_library.hpp"

namespace magfem {

namespace {

const std::string cli = "<command line>";

void list_entries(const MaterialLibrary& lib) {
  for (const auto& name : lib.names()) {
    std::string line = name;
    line.resize(14, ' ');
    line += to_string(lib.find(name)->kind);
    std::string aliases;
    for (const auto& [alias, entry] : lib.aliases())
      if (entry == name)
        aliases += (aliases.empty() ? "" : ", ") + alias;
    std::cout << line << (aliases.empty() ? "" : "  (also " + aliases + ")") << "\n";
  }
}

void export_curve(const MaterialLibrary& lib, const std::string& name) {
  const Material* m = lib.find(name);
  if (!m) {
    std::string names;
    for (const auto& n : lib.names())
      names += (names.empty() ? "" : ", ") + n;
    throw InputError(cli, 0, "--export",
                     "unknown library material '" + name + "' (library: " + names + ")");
  }
  if (!m->curve)
    throw InputError(cli, 0, "--export",
                     "'" + name + "' is a " + to_string(m->kind) +
                         " material: only soft materials have a B-H table");
  std::cout << "# " << m->name << ": " << m->source << "\n";
  write_bh_table_file(std::cout, *m->curve);
}

} // namespace

const OptionTable<MaterialsOptions>& materials_option_table() {
  static const auto table =
      OptionTable<MaterialsOptions>("materials")
          .value("--export", "NAME", [](MaterialsOptions& o, auto&, const std::string& v) {
            o.export_names.push_back(v);
          });
  return table;
}

int run_materials_command(const std::vector<std::string>& args) {
  MaterialsOptions options;
  const auto positional = materials_option_table().parse(args, options);
  if (!positional.empty())
    throw InputError(cli, 0, positional[0], "magfem materials takes no arguments (--export NAME)");
  if (options.export_names.size() > 1)
    throw InputError(cli, 0, "--export", "give one library name: --export NAME");
  const MaterialLibrary& lib = MaterialLibrary::bundled();
  if (options.export_names.empty())
    list_entries(lib);
  else
    export_curve(lib, options.export_names[0]);
  return 0;
}

} // namespace magfem
