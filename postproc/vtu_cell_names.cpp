#include "postproc/vtu_cell_names.hpp"

#include <algorithm>
#include <stdexcept>

namespace magfem {

void add_cell_names(VtuGrid& grid, const std::string& id_array, const std::string& cell_name,
                    const std::string& table_name, const std::vector<std::string>& names,
                    const std::string& negative_name) {
  const auto ids = std::find_if(grid.cell_data.begin(), grid.cell_data.end(),
                                [&](const VtuArray& a) { return a.name == id_array; });
  if (ids == grid.cell_data.end())
    throw std::invalid_argument("add_cell_names: no cell array " + id_array);
  VtuStrings per_cell{cell_name, {}};
  per_cell.values.reserve(ids->values.size());
  for (const double v : ids->values) {
    const int id = static_cast<int>(v);
    if (id >= static_cast<int>(names.size()))
      throw std::invalid_argument("add_cell_names: " + id_array + " " + std::to_string(id) +
                                  " has no name");
    per_cell.values.push_back(id < 0 ? negative_name : names[static_cast<std::size_t>(id)]);
  }
  grid.cell_names.push_back(std::move(per_cell));
  grid.field_data.push_back({table_name, names});
}

void add_region_and_material_names(VtuGrid& grid, const std::vector<std::string>& region_names,
                                   const std::vector<std::string>& material_names) {
  add_cell_names(grid, "region_id", "region", "region_names", region_names);
  add_cell_names(grid, "material_id", "material", "material_names", material_names);
}

} // namespace magfem
