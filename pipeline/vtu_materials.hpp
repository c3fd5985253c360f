#pragma once
// The material of every region as the VTU's `material` cell field numbers them: "air" is 0,
// then each material in the order its first region appears (2D and 3D alike); and the
// regions' names, index = region_id.
#include <map>
#include <string>
#include <vector>

#include "casefile/case_spec.hpp"

namespace magfem {

struct VtuMaterials {
  std::vector<std::string> names = {"air"};
  std::vector<int> of_region; // index into names, per region
  std::vector<std::string> region_names;
};

inline VtuMaterials vtu_materials(const std::vector<RegionSpec>& regions) {
  VtuMaterials m;
  std::map<std::string, int> index = {{"air", 0}};
  for (const auto& r : regions) {
    auto [it, fresh] = index.emplace(r.material->name, static_cast<int>(m.names.size()));
    if (fresh)
      m.names.push_back(r.material->name);
    m.of_region.push_back(it->second);
    m.region_names.push_back(r.name);
  }
  return m;
}

} // namespace magfem
