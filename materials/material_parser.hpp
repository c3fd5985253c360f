#pragma once
// Reading materials from YAML: the `materials:` map of a case file, single entries and B-H
// tables. Every error is an InputError naming the file, the line and the field, e.g.
// `materials.iron.bh[3]` for the fourth row of a B-H table.
//
// Case-file entry forms:
//   pm:    {kind: magnet, B_r: 1.0, mu_r: 1.05}
//   core:  {kind: linear, mu_r: 1000}
//   iron:  {kind: soft, bh: [[0, 0], [100, 0.5], [300, 1.2], [1000, 1.5], [10000, 1.9]]}
//   iron2: {kind: soft, bh_file: steel.csv}  # the same table in a CSV file (bh_table_file.hpp)
//   n42:   {library: N42, B_r: 1.30}   # a bundled entry; fields of its kind may be overridden
//   steel: {library: steel_1010}
// Optional in every entry: `source: "..."` (where the data come from, shown in reports).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/yaml_node.hpp"
#include "materials/bh_curve.hpp"
#include "materials/material.hpp"
#include "materials/material_library.hpp"

namespace magfem {

// Parses the case file's `materials:` map (name -> entry). Unknown keys, unknown kinds,
// unknown library names, duplicate names and bad values are InputErrors.
std::map<std::string, Material> parse_materials(const YamlNode& materials_map,
                                                const MaterialLibrary& library);

// The material called `name`: case materials first, then the library (aliases included);
// otherwise an InputError at `where` (file, line, field of the referring node) listing the
// known names. The reference points into `case_materials` or `library`, which must outlive it.
const Material& resolve_material(const std::string& name,
                                 const std::map<std::string, Material>& case_materials,
                                 const MaterialLibrary& library, const YamlNode& where);

// One self-contained entry (`kind` required). Accepted keys: those of its kind (linear:
// mu_r; magnet: B_r, mu_r; soft: exactly one of bh and bh_file) plus `kind` and `extra_keys` (the
// caller reads those). `source` is taken from the entry when present, else `default_source`.
Material parse_material_entry(const std::string& name, const YamlNode& entry,
                              const std::vector<std::string>& extra_keys,
                              const std::string& default_source);

// A B-H table: a list of [H A/m, B T] rows. A row the curve rejects (see BhCurve) is
// reported at that row's line with field `<path>[i]`.
std::shared_ptr<const BhCurve> parse_bh_table(const YamlNode& bh);

// Fails on a map key that appears twice (yaml-cpp keeps both), naming its line.
void reject_duplicate_keys(const YamlNode& map);

} // namespace magfem
