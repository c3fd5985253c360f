#include "materials/material_library.hpp"

#include "materials/library_text.hpp"
#include "materials/material_parser.hpp"

namespace magfem {

const MaterialLibrary& MaterialLibrary::bundled() {
  // Parsed once; an error here is a defect of library.yaml, caught by the unit tests.
  static const MaterialLibrary library = from_yaml(
      YamlNode::load_string(std::string(bundled_library_text()), "materials/library.yaml"));
  return library;
}

MaterialLibrary MaterialLibrary::from_yaml(const YamlNode& root) {
  root.allow_keys({"materials"});
  const YamlNode map = root.at("materials");
  reject_duplicate_keys(map);
  MaterialLibrary lib;
  for (const auto& name : map.keys()) {
    const YamlNode entry = map.at(name);
    if (lib.find(name))
      entry.fail("'" + name + "' is already an alias of another entry");
    Material m = parse_material_entry(name, entry, {"source", "aliases"}, "");
    if (m.source.empty())
      entry.at("source"); // reports the missing field
    if (const auto aliases = entry.find("aliases")) {
      for (const auto& alias : aliases->items()) {
        const std::string a = alias.as_string();
        if (lib.find(a) || a == name)
          alias.fail("'" + a + "' is already a material name");
        lib.aliases_.emplace(a, name);
      }
    }
    lib.order_.push_back(name);
    lib.materials_.emplace(name, std::move(m));
  }
  return lib;
}

const Material* MaterialLibrary::find(const std::string& name) const {
  if (const auto it = materials_.find(name); it != materials_.end())
    return &it->second;
  if (const auto al = aliases_.find(name); al != aliases_.end())
    return &materials_.at(al->second);
  return nullptr;
}

} // namespace magfem
