#include "materials/material_parser.hpp"

#include <set>

#include "core/did_you_mean.hpp"
#include "materials/bh_table_file.hpp"

namespace magfem {

namespace {

// Law parameters each kind accepts.
std::vector<std::string> law_keys(MaterialKind kind) {
  switch (kind) {
  case MaterialKind::linear:
    return {"mu_r"};
  case MaterialKind::magnet:
    return {"B_r", "mu_r", "HcJ_kApm", "alpha_Br_pct_per_K", "beta_HcJ_pct_per_K"};
  case MaterialKind::soft:
    return {"bh", "bh_file"};
  }
  return {};
}

// The knee data of a magnet (magnet_knee.hpp), each optional: H_cJ in kA/m (> 0) and the
// temperature coefficients in %/K (any sign: ferrite's H_cJ rises with temperature).
void read_knee_keys(MagnetKnee& knee, const YamlNode& entry) {
  if (const auto n = entry.find("HcJ_kApm"))
    knee.HcJ_Apm = n->as_positive() * 1e3;
  if (const auto n = entry.find("alpha_Br_pct_per_K"))
    knee.alpha_pct_per_K = n->as_double();
  if (const auto n = entry.find("beta_HcJ_pct_per_K"))
    knee.beta_pct_per_K = n->as_double();
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string comma_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

MaterialKind parse_kind(const YamlNode& node) {
  const std::string text = node.as_string();
  if (text == "linear")
    return MaterialKind::linear;
  if (text == "magnet")
    return MaterialKind::magnet;
  if (text == "soft")
    return MaterialKind::soft;
  node.fail("unknown material kind '" + text + "' (expected linear, magnet or soft)");
}

std::string location(const YamlNode& node) {
  return node.file() + ":" + std::to_string(node.line());
}

// The curve of a soft material: exactly one of `bh` (inline rows) and `bh_file` (a CSV file).
std::shared_ptr<const BhCurve> parse_soft_curve(const YamlNode& entry) {
  const auto bh = entry.find("bh");
  const auto bh_file = entry.find("bh_file");
  if (bh && bh_file)
    bh_file->fail("give either 'bh' (a table) or 'bh_file' (a CSV file), not both");
  if (bh_file)
    return load_bh_table_file(*bh_file);
  if (!bh)
    entry.fail("a soft material needs its B-H curve: 'bh' (a list of [H A/m, B T] rows) or "
               "'bh_file' (a CSV file with columns H_Apm,B_T)");
  return parse_bh_table(*bh);
}

// Overrides the law parameters of `m` (a library entry) with those given in `entry`.
std::string apply_overrides(Material& m, const YamlNode& entry) {
  std::string changed;
  for (const auto& key : law_keys(m.kind)) {
    const auto node = entry.find(key);
    if (!node)
      continue;
    changed += (changed.empty() ? "" : ", ") + key;
    if (key == "mu_r")
      m.mu_r = node->as_positive();
    if (key == "B_r")
      m.B_r = node->as_positive();
  }
  if (m.kind == MaterialKind::magnet)
    read_knee_keys(m.knee, entry);
  if (m.kind == MaterialKind::soft && (entry.has("bh") || entry.has("bh_file")))
    m = Material::make_soft(m.name, parse_soft_curve(entry), m.source);
  return changed;
}

Material parse_library_reference(const std::string& name, const YamlNode& entry,
                                 const MaterialLibrary& library) {
  const YamlNode ref = entry.at("library");
  const std::string ref_name = ref.as_string();
  const Material* base = library.find(ref_name);
  if (!base)
    ref.fail("unknown library material '" + ref_name +
             "' (library: " + comma_list(library.names()) + ")");
  entry.allow_keys(joined({"library", "source"}, law_keys(base->kind)));
  Material m = *base;
  m.name = name;
  const std::string changed = apply_overrides(m, entry);
  m.source = entry.get_string(
      "source", base->source +
                    (changed.empty() ? "" : "; overridden in " + location(entry) + ": " + changed));
  return m;
}

} // namespace

void reject_duplicate_keys(const YamlNode& map) {
  if (!map.is_map())
    map.fail("expected a map");
  std::set<std::string> seen;
  for (const auto& kv : map.raw()) {
    const auto key = map.key_text(kv.first);
    if (!seen.insert(key).second)
      throw InputError(map.file(), kv.first.Mark().line + 1,
                       map.path().empty() ? key : map.path() + "." + key,
                       "'" + key + "' is defined twice");
  }
}

std::shared_ptr<const BhCurve> parse_bh_table(const YamlNode& bh) {
  const auto rows = bh.items();
  std::vector<double> h, b;
  for (const auto& row : rows) {
    const auto hb = row.as_doubles(2);
    h.push_back(hb[0]);
    b.push_back(hb[1]);
  }
  try {
    check_bh_table_plausible(h, b);
    return std::make_shared<const BhCurve>(std::move(h), std::move(b));
  } catch (const BhTableError& e) {
    if (e.row() < rows.size())
      rows[e.row()].fail(e.reason());
    bh.fail(e.reason());
  }
}

Material parse_material_entry(const std::string& name, const YamlNode& entry,
                              const std::vector<std::string>& extra_keys,
                              const std::string& default_source) {
  const MaterialKind kind = parse_kind(entry.at("kind"));
  entry.allow_keys(joined(joined({"kind"}, law_keys(kind)), extra_keys));
  const std::string source = entry.get_string("source", default_source);
  switch (kind) {
  case MaterialKind::linear:
    return Material::make_linear(name, entry.at("mu_r").as_positive(), source);
  case MaterialKind::magnet: {
    Material m = Material::make_magnet(name, entry.at("B_r").as_positive(),
                                       entry.at("mu_r").as_positive(), source);
    read_knee_keys(m.knee, entry);
    return m;
  }
  case MaterialKind::soft:
    return Material::make_soft(name, parse_soft_curve(entry), source);
  }
  entry.fail("unhandled material kind");
}

std::map<std::string, Material> parse_materials(const YamlNode& materials_map,
                                                const MaterialLibrary& library) {
  reject_duplicate_keys(materials_map);
  std::map<std::string, Material> out;
  for (const auto& name : materials_map.keys()) {
    const YamlNode entry = materials_map.at(name);
    // Check the spelling of every key first, so a typo is named as such.
    entry.allow_keys({"kind", "library", "mu_r", "B_r", "HcJ_kApm", "alpha_Br_pct_per_K",
                      "beta_HcJ_pct_per_K", "bh", "bh_file", "source"});
    if (entry.has("library") && entry.has("kind"))
      entry.at("kind").fail("give either 'kind' or 'library', not both");
    if (entry.has("library")) {
      out.emplace(name, parse_library_reference(name, entry, library));
    } else if (entry.has("kind")) {
      out.emplace(name,
                  parse_material_entry(name, entry, {"source"}, "case file " + location(entry)));
    } else {
      entry.fail("a material needs 'kind' (linear, magnet or soft) or 'library' (one of: " +
                 comma_list(library.names()) + ")");
    }
  }
  return out;
}

const Material& resolve_material(const std::string& name,
                                 const std::map<std::string, Material>& case_materials,
                                 const MaterialLibrary& library, const YamlNode& where) {
  if (const auto it = case_materials.find(name); it != case_materials.end())
    return it->second;
  if (const Material* m = library.find(name))
    return *m;
  std::vector<std::string> case_names;
  for (const auto& kv : case_materials)
    case_names.push_back(kv.first);
  std::vector<std::string> all = case_names;
  for (const auto& n : library.names())
    all.push_back(n);
  where.fail("unknown material '" + name + "'" + did_you_mean(name, all) + " (case materials: " +
             comma_list(case_names) + "; library: " + comma_list(library.names()) + ")");
}

} // namespace magfem
