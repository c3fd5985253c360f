#pragma once
// `magfem mesh CASE.yaml [--out DIR] [--order 1|2] [--mesh-scale S] [--plane x|y|z]
// [--param NAME=VALUE]`: the mesh `magfem solve` would solve on, without solving it, to look
// at before a long run. Writes into DIR (default out/<case>_mesh), all or nothing:
// summary.json (elements, nodes, unknowns at the order, per region its elements, size and
// smallest and largest element edge, mesh quality, the mesher's warnings), mesh.vtu (region_id
// and region name per cell, for ParaView) and mesh.png (2D: the mesh coloured by region; 3D: its
// cut by the coordinate plane through the origin normal to --plane, default y: the xz plane).
#include <string>
#include <vector>

#include "core/option_table.hpp"

namespace magfem {

int run_mesh_command(const std::vector<std::string>& args);
std::vector<OptionInfo> mesh_option_infos();

} // namespace magfem
