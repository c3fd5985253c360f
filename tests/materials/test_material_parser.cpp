// The case file's `materials:` map: forms, overrides, and errors with file, line and field.
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "materials/material_parser.hpp"

using magfem::InputError;
using magfem::Material;
using magfem::MaterialKind;
using magfem::MaterialLibrary;
using magfem::YamlNode;

namespace {

std::map<std::string, Material> parse(const std::string& text) {
  const auto root = YamlNode::load_string(text, "case.yaml");
  return magfem::parse_materials(root.at("materials"), MaterialLibrary::bundled());
}

// Parses and returns the InputError; fails the test when none is thrown.
InputError parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", 0, "", "");
}

} // namespace

TEST(MaterialParser, ReadsEveryEntryForm) {
  const auto m = parse(R"(materials:
  pm:    {kind: magnet, B_r: 1.0, mu_r: 1.0}
  n42:   {library: N42, B_r: 1.30}
  core:  {kind: linear, mu_r: 1000}
  iron:  {kind: soft, bh: [[0, 0], [100, 0.5], [300, 1.2], [1000, 1.5], [10000, 1.9]]}
  steel: {library: steel_1010}
)");
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m.at("pm").kind, MaterialKind::magnet);
  EXPECT_EQ(m.at("pm").B_r, 1.0);
  EXPECT_EQ(m.at("n42").kind, MaterialKind::magnet);
  EXPECT_EQ(m.at("n42").name, "n42");
  EXPECT_EQ(m.at("n42").B_r, 1.30);  // overridden
  EXPECT_EQ(m.at("n42").mu_r, 1.11); // kept from the library
  EXPECT_NE(m.at("n42").source.find("overridden"), std::string::npos);
  EXPECT_EQ(m.at("core").mu_r, 1000);
  ASSERT_TRUE(m.at("iron").curve);
  EXPECT_NEAR(m.at("iron").curve->b_of_h(300), 1.2, 1e-15);
  EXPECT_EQ(m.at("steel").curve, MaterialLibrary::bundled().find("steel_1010")->curve);
}

TEST(MaterialParser, BadTableRowIsNamedWithFileLineAndField) {
  const auto e = parse_error(R"(materials:
  iron:
    kind: soft
    bh:
      - [0, 0]
      - [100, 0.5]
      - [300, 1.2]
      - [250, 1.5]
      - [10000, 1.9]
)");
  EXPECT_EQ(e.file(), "case.yaml");
  EXPECT_EQ(e.line(), 8);
  EXPECT_EQ(e.field(), "materials.iron.bh[3]");
  EXPECT_NE(e.reason().find("H must increase"), std::string::npos) << e.what();
}

TEST(MaterialParser, NonPhysicalFinalSlopeIsNamed) {
  const auto e = parse_error("materials:\n  iron: {kind: soft, bh: [[100, 0.5], [1e6, 0.6]]}\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.field(), "materials.iron.bh[1]");
  EXPECT_NE(e.reason().find("mu0"), std::string::npos) << e.what();
}

TEST(MaterialParser, MalformedRowsAndShortTables) {
  EXPECT_EQ(parse_error("materials:\n  i: {kind: soft, bh: [[0, 0], [100]]}\n").field(),
            "materials.i.bh[1]");
  EXPECT_EQ(parse_error("materials:\n  i: {kind: soft, bh: [[100, 1]]}\n").field(),
            "materials.i.bh[0]");
  EXPECT_EQ(parse_error("materials:\n  i: {kind: soft, bh: 3}\n").field(), "materials.i.bh");
}

TEST(MaterialParser, UnknownKeysAreRejected) {
  auto e = parse_error(
      "materials:\n  pm:\n    kind: magnet\n    B_r: 1\n    mu_r: 1\n    colour: red\n");
  EXPECT_EQ(e.line(), 6);
  EXPECT_EQ(e.field(), "materials.pm.colour");
  // A key of another kind is unknown for this one.
  e = parse_error("materials:\n  c: {kind: linear, mu_r: 2, B_r: 1}\n");
  EXPECT_EQ(e.field(), "materials.c.B_r");
  e = parse_error("materials:\n  s: {library: steel_1010, B_r: 1}\n");
  EXPECT_EQ(e.field(), "materials.s.B_r");
  e = parse_error("materials:\n  s: {library: N42, kind: magnet}\n");
  EXPECT_EQ(e.field(), "materials.s.kind");
}

TEST(MaterialParser, UnknownKindsAndLibraryNamesAreRejected) {
  auto e = parse_error("materials:\n  x: {kind: plastic, mu_r: 1}\n");
  EXPECT_EQ(e.field(), "materials.x.kind");
  e = parse_error("materials:\n  x: {library: N99}\n");
  EXPECT_EQ(e.field(), "materials.x.library");
  EXPECT_NE(e.reason().find("N42"), std::string::npos) << "should list the known names";
  e = parse_error("materials:\n  x: {source: nothing}\n");
  EXPECT_EQ(e.field(), "materials.x");
}

TEST(MaterialParser, LawParametersAreChecked) {
  EXPECT_EQ(parse_error("materials:\n  m: {kind: magnet, B_r: 0, mu_r: 1}\n").field(),
            "materials.m.B_r");
  EXPECT_EQ(parse_error("materials:\n  m: {kind: magnet, B_r: 1.2}\n").field(), "materials.m.mu_r");
  EXPECT_EQ(parse_error("materials:\n  m: {kind: magnet, B_r: 1.2, mu_r: -1}\n").field(),
            "materials.m.mu_r");
  EXPECT_EQ(parse_error("materials:\n  c: {kind: linear, mu_r: 0}\n").field(), "materials.c.mu_r");
  EXPECT_EQ(parse_error("materials:\n  c: {library: N42, B_r: -1}\n").field(), "materials.c.B_r");
}

TEST(MaterialParser, DuplicateNamesAreRejected) {
  const auto e =
      parse_error("materials:\n  a: {kind: linear, mu_r: 2}\n  a: {kind: linear, mu_r: 3}\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "materials.a");
}

TEST(MaterialParser, ResolvesCaseMaterialsFirstThenTheLibrary) {
  const auto root = YamlNode::load_string(
      "materials:\n  N42: {kind: magnet, B_r: 1.0, mu_r: 1.0}\nregions:\n  - {material: foo}\n",
      "case.yaml");
  const auto& lib = MaterialLibrary::bundled();
  const auto mats = magfem::parse_materials(root.at("materials"), lib);
  const auto where = root.at("regions")[0].at("material");
  EXPECT_EQ(magfem::resolve_material("N42", mats, lib, where).B_r, 1.0); // the case's own
  EXPECT_EQ(&magfem::resolve_material("M-19", mats, lib, where), lib.find("M-19"));
  EXPECT_EQ(&magfem::resolve_material("vacuum", mats, lib, where), lib.find("air"));
  try {
    magfem::resolve_material("foo", mats, lib, where);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.yaml");
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.field(), "regions[0].material");
    EXPECT_NE(e.reason().find("steel_1010"), std::string::npos) << e.what();
  }
}
