#include "cli/materials_command.hpp"

#include <cstdio>
#include <iostream>

#include "core/did_you_mean.hpp"
#include "core/input_error.hpp"
#include "materials/bh_table_file.hpp"
#include "materials/material_library.hpp"

namespace magfem {

namespace {

const std::string cli = "<command line>";

std::string format(const char* fmt, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// A magnet's knee data in a few words: H_cJ at 20 C with its temperature coefficient, or why
// the demagnetization check has no knee for it.
std::string knee_brief(const Material& m) {
  if (!m.knee.HcJ_Apm)
    return "no knee data";
  std::string s = format("H_cJ %.0f kA/m", *m.knee.HcJ_Apm / 1e3);
  if (m.knee.beta_pct_per_K)
    s += format(" (%+.2f %%/K)", *m.knee.beta_pct_per_K);
  return s;
}

void list_entries(const MaterialLibrary& lib) {
  for (const auto& name : lib.names()) {
    const Material& m = *lib.find(name);
    std::string line = name;
    line.resize(14, ' ');
    line += to_string(m.kind);
    if (m.is_magnet())
      line += format("  B_r %.3g T, ", m.B_r) + knee_brief(m);
    std::string aliases;
    for (const auto& [alias, entry] : lib.aliases())
      if (entry == name)
        aliases += (aliases.empty() ? "" : ", ") + alias;
    std::cout << line << (aliases.empty() ? "" : "  (also " + aliases + ")") << "\n";
  }
}

const Material& entry(const MaterialLibrary& lib, const std::string& name,
                      const std::string& field) {
  if (const Material* m = lib.find(name))
    return *m;
  std::string names;
  for (const auto& n : lib.names())
    names += (names.empty() ? "" : ", ") + n;
  throw InputError(cli, 0, field,
                   "unknown library material '" + name + "'" + did_you_mean(name, lib.names()) +
                       " (library: " + names + ")");
}

// Temperatures at which `magfem materials NAME` gives a magnet's knee: room temperature up
// to the 150 C that N grades without a suffix are not rated for.
constexpr double knee_table_C[] = {20, 60, 80, 100, 120, 150};

// One entry in full: what the solver and the demagnetization check take from it, and where
// the numbers come from.
void describe_entry(const Material& m) {
  std::cout << m.name << " (" << to_string(m.kind) << ")\n";
  if (m.is_magnet()) {
    const auto& k = m.knee;
    std::cout << format("  B_r    %.4g T at 20 C", m.B_r)
              << (k.alpha_pct_per_K ? format(", %+.3g %%/K", *k.alpha_pct_per_K) : "") << "\n"
              << format("  mu_r   %.4g (recoil)\n", m.mu_r);
    if (!k.HcJ_Apm) {
      std::cout << "  H_cJ   unknown: the demagnetization check reports knee_T null (give "
                   "HcJ_kApm, and beta_HcJ_pct_per_K off 20 C, in the case)\n";
    } else {
      std::cout << format("  H_cJ   %.4g kA/m at 20 C", *k.HcJ_Apm / 1e3)
                << (k.beta_pct_per_K ? format(", %+.3g %%/K", *k.beta_pct_per_K) : "") << "\n"
                << "  knee   B along M below which the magnet loses remanence for good,\n"
                   "         B_r(T) - mu0 mu_r H_cJ(T) (a region's temperature_C picks T):\n";
      for (const double T : knee_table_C) {
        if (T != MagnetKnee::reference_C && !(k.alpha_pct_per_K && k.beta_pct_per_K))
          break; // no temperature coefficients: 20 C only
        std::cout << format("         %5.0f C", T)
                  << format("  %7.3f T\n", *m.at_temperature(T).knee_T());
      }
    }
  } else if (m.kind == MaterialKind::linear) {
    std::cout << format("  mu_r   %.6g\n", m.mu_r);
  } else {
    std::cout << "  B-H    " << m.curve->h_table().size()
              << format(" points up to H = %.4g kA/m", m.curve->h_table().back() / 1e3)
              << format(", B = %.4g T (magfem materials --export NAME)\n",
                        m.curve->b_table().back());
  }
  std::cout << "  source " << m.source << "\n";
}

void export_curve(const MaterialLibrary& lib, const std::string& name) {
  const Material* m = &entry(lib, name, "--export");
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
  if (positional.size() > 1)
    throw InputError(cli, 0, positional[1],
                     "magfem materials takes one name (magfem materials NAME)");
  if (options.export_names.size() > 1)
    throw InputError(cli, 0, "--export", "give one library name: --export NAME");
  if (!positional.empty() && !options.export_names.empty())
    throw InputError(cli, 0, "--export", "give either NAME or --export NAME");
  const MaterialLibrary& lib = MaterialLibrary::bundled();
  if (!positional.empty())
    describe_entry(entry(lib, positional[0], "NAME"));
  else if (options.export_names.empty())
    list_entries(lib);
  else
    export_curve(lib, options.export_names[0]);
  return 0;
}

} // namespace magfem
