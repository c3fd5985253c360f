#pragma once
// A named collection of materials read from a YAML document. The bundled one comes from
// materials/library.yaml, embedded into the program at build time (see library_text.hpp).
//
// Document layout (the same for user libraries):
//   materials:
//     <name>:
//       kind: linear | magnet | soft
//       mu_r: ...        # linear, magnet (recoil)
//       B_r: ...         # magnet, in T
//       bh: [[H, B], ...] # soft: rows in A/m and T (see BhCurve for the checks)
//       source: "..."    # required: where the numbers come from
//       aliases: [...]   # optional other names
#include <map>
#include <string>
#include <vector>

#include "core/yaml_node.hpp"
#include "materials/material.hpp"

namespace magfem {

class MaterialLibrary {
public:
  // The bundled library, parsed on first use and kept for the life of the program.
  static const MaterialLibrary& bundled();
  // Parses a library document (root with a `materials:` map); InputError with file, line and
  // field on any bad entry, unknown key, missing `source` or duplicate name/alias.
  static MaterialLibrary from_yaml(const YamlNode& root);

  // The entry called `name` or having it as an alias (exact spelling); nullptr if unknown.
  // The pointer stays valid as long as the library (for bundled(): forever).
  const Material* find(const std::string& name) const;
  // Entry names in file order (aliases not included).
  std::vector<std::string> names() const { return order_; }
  // alias -> entry name
  const std::map<std::string, std::string>& aliases() const { return aliases_; }

private:
  std::vector<std::string> order_;
  std::map<std::string, Material> materials_;
  std::map<std::string, std::string> aliases_;
};

} // namespace magfem
