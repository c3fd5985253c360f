// The bundled material library: every entry loads, the thesis grades carry the thesis numbers,
// the soft irons are physical, and the embedded text is the file in the source tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/constants.hpp"
#include "materials/library_text.hpp"
#include "materials/material_library.hpp"
#include "tests/test_paths.hpp"

using magfem::Material;
using magfem::MaterialKind;
using magfem::MaterialLibrary;
using magfem::mu0;
using magfem::YamlNode;

namespace {
const Material& get(const std::string& name) {
  const Material* m = MaterialLibrary::bundled().find(name);
  if (!m)
    throw std::runtime_error("missing bundled material " + name);
  return *m;
}
} // namespace

TEST(MaterialLibrary, EveryBundledEntryLoadsWithASource) {
  const auto& lib = MaterialLibrary::bundled();
  const std::vector<std::string> expected{
      "air",     "N35",         "N42",        "N45",        "N52",  "VACODYM633HR", "NdFeB_bonded",
      "Sm2Co17", "ferrite_Y30", "steel_1010", "steel_1018", "M-19", "pure_iron"};
  EXPECT_EQ(lib.names(), expected);
  for (const auto& name : lib.names()) {
    const Material& m = get(name);
    EXPECT_EQ(m.name, name);
    EXPECT_GT(m.source.size(), 20u) << name << " needs a real source text";
    EXPECT_GT(m.mu_r, 0.0) << name;
    if (m.is_magnet()) {
      EXPECT_GT(m.B_r, 0.0) << name;
    }
    EXPECT_EQ(m.kind == MaterialKind::soft, m.curve != nullptr) << name;
  }
}

TEST(MaterialLibrary, ThesisGradesCarryTheThesisNumbers) {
  // van Ninhuijs thesis Tables 6.2 / 6.3: nominal value of each B_r range, typical mu_r.
  EXPECT_EQ(get("N42").B_r, 1.31);
  EXPECT_EQ(get("N42").mu_r, 1.11);
  EXPECT_EQ(get("N45").B_r, 1.345);
  EXPECT_EQ(get("N45").mu_r, 1.14);
  EXPECT_EQ(get("VACODYM633HR").B_r, 1.35);
  EXPECT_EQ(get("VACODYM633HR").mu_r, 1.078);
  EXPECT_EQ(get("NdFeB_bonded").B_r, 0.65);
  EXPECT_GE(get("Sm2Co17").B_r, 1.05);
  EXPECT_LE(get("Sm2Co17").B_r, 1.10);
}

TEST(MaterialLibrary, AliasesResolveToTheirEntry) {
  const auto& lib = MaterialLibrary::bundled();
  EXPECT_EQ(lib.find("vacuum"), lib.find("air"));
  EXPECT_EQ(lib.find("SmCo"), lib.find("Sm2Co17"));
  EXPECT_EQ(lib.find("ferrite"), lib.find("ferrite_Y30"));
  EXPECT_EQ(lib.find("n42"), nullptr); // names are exact
  EXPECT_EQ(lib.find("unobtainium"), nullptr);
  EXPECT_EQ(get("air").mu_r, 1.0);
}

TEST(MaterialLibrary, SoftIronsAreMonotoneAndSaturate) {
  for (const std::string name : {"steel_1010", "steel_1018", "M-19", "pure_iron"}) {
    const auto& c = *get(name).curve;
    const auto& h = c.h_table();
    const auto& b = c.b_table();
    EXPECT_GE(h.size(), 10u) << name;
    EXPECT_LE(h.size(), 26u) << name; // 25 given rows plus the origin
    EXPECT_GE(b.back(), 2.0) << name << " table should reach saturation (~2 T)";
    double prev = -1, mu_r_max = 0;
    for (int i = 0; i <= 20000; ++i) {
      const double x = 2 * h.back() * i / 20000.0;
      const double y = c.b_of_h(x);
      EXPECT_GT(y, prev) << name << " at H = " << x;
      prev = y;
      if (x > 0)
        mu_r_max = std::max(mu_r_max, y / x / mu0);
    }
    // Plausibility of the data: maximum relative permeability of structural steels and
    // electrical steels lies between a few hundred and a few ten thousand.
    EXPECT_GT(mu_r_max, 300) << name;
    EXPECT_LT(mu_r_max, 30000) << name;
    // Saturated: at 2.5 T the differential permeability is that of vacuum (within 1 %).
    EXPECT_NEAR(c.dbdh(c.h_of_b(2.5)), mu0, 0.01 * mu0) << name;
    // Saturation polarization J = B - mu0 H of iron alloys lies between 1.8 and 2.2 T.
    const double j = 2.5 - mu0 * c.h_of_b(2.5);
    EXPECT_GT(j, 1.8) << name;
    EXPECT_LT(j, 2.2) << name;
  }
}

TEST(MaterialLibrary, EmbeddedTextIsTheSourceFile) {
  std::ifstream in(std::string(magfem::test::source_dir()) + "/materials/library.yaml");
  ASSERT_TRUE(in.good());
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(magfem::bundled_library_text(), s.str());
}

TEST(MaterialLibrary, FromYamlRequiresSourcesAndUniqueNames) {
  const auto lib = MaterialLibrary::from_yaml(YamlNode::load_string(
      "materials:\n  a: {kind: linear, mu_r: 2, source: x, aliases: [b]}\n", "lib.yaml"));
  EXPECT_NE(lib.find("b"), nullptr);
  EXPECT_THROW(MaterialLibrary::from_yaml(
                   YamlNode::load_string("materials:\n  a: {kind: linear, mu_r: 2}\n", "l.yaml")),
               magfem::InputError);
  try {
    MaterialLibrary::from_yaml(
        YamlNode::load_string("materials:\n  a: {kind: linear, mu_r: 2, source: x, aliases: [b]}\n"
                              "  b: {kind: linear, mu_r: 3, source: y}\n",
                              "l.yaml"));
    FAIL();
  } catch (const magfem::InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "materials.b");
  }
}
