#pragma once
// Names for the id cell arrays of a VtuGrid (region_id, material_id). ParaView colours a cell
// string array categorically, one colour per name with the names in the legend, which an id
// array cannot do; the table as field data lets a script map ids to names. Both are written:
//   cell data  region, material               the cell's region and material name
//   field data region_names, material_names   index = id
#include <string>
#include <vector>

#include "postproc/vtu_writer.hpp"

namespace magfem {

// Adds the cell string array `cell_name` (names[id] of the cell array `id_array`, or
// negative_name for an id < 0: the background air's region_id -1) and the field data
// `table_name` (names). Throws std::invalid_argument if id_array is missing or an id >= names.
void add_cell_names(VtuGrid& grid, const std::string& id_array, const std::string& cell_name,
                    const std::string& table_name, const std::vector<std::string>& names,
                    const std::string& negative_name = "air");

// region_id and material_id named: region_names one per case region (index = region_id; -1 is
// the background air), material_names index = material_id.
void add_region_and_material_names(VtuGrid& grid, const std::vector<std::string>& region_names,
                                   const std::vector<std::string>& material_names);

} // namespace magfem
