// B-H tables from CSV files (`bh_file:`): the same curve as inline, bit for bit; the header
// forms; errors naming the case file or the CSV file with its line; the plausibility checks
// (swapped columns) on inline and file tables alike.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "materials/bh_table_file.hpp"
#include "materials/material_parser.hpp"

using magfem::InputError;
using magfem::Material;
using magfem::MaterialLibrary;
using magfem::YamlNode;

namespace {

namespace fs = std::filesystem;

// A fresh directory for one test's case file and tables.
fs::path test_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "magfem_tests" / "bh_table_file" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::map<std::string, Material> parse_case(const fs::path& case_file) {
  const auto root = YamlNode::load_file(case_file.string());
  return magfem::parse_materials(root.at("materials"), MaterialLibrary::bundled());
}

InputError case_error(const fs::path& case_file) {
  try {
    parse_case(case_file);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << case_file;
  return InputError("", 0, "", "");
}

bool says(const InputError& e, const std::string& text) {
  return std::string(e.what()).find(text) != std::string::npos;
}

// The curve data and every derived number must be identical, not close.
void expect_identical(const magfem::BhCurve& a, const magfem::BhCurve& b) {
  EXPECT_EQ(a.h_table(), b.h_table());
  EXPECT_EQ(a.b_table(), b.b_table());
  EXPECT_EQ(a.initial_slope(), b.initial_slope());
  for (const double h : {0.0, 1.0, 123.456, 2000.0, 1e5, 1e7}) {
    EXPECT_EQ(a.b_of_h(h), b.b_of_h(h));
    EXPECT_EQ(a.dbdh(h), b.dbdh(h));
  }
}

} // namespace

// The header's columns in either order, no header, comments, CRLF and spaces: one curve, and
// the same bits as the table written inline in the case file.
TEST(BhTableFile, FileTableEqualsTheInlineTableBitForBit) {
  const auto dir = test_dir("equal");
  write(dir / "hb.csv", "# steel, H in A/m, B in T\nH_Apm,B_T\n238.7,0.2003\n358.1, 0.40045\n"
                        "\n1591.5,1.302\n159155,2.2\n");
  write(dir / "bh.csv",
        "\xEF\xBB\xBF"
        "B_T,H_Apm\r\n0.2003,238.7\r\n0.40045,358.1\r\n1.302,1591.5\r\n2.2,159155\r\n");
  write(dir / "plain.csv", "238.7,0.2003\n358.1,0.40045\n1591.5,1.302\n159155,2.2\n");
  write(dir / "case.yaml", R"(materials:
  inline: {kind: soft, bh: [[238.7, 0.2003], [358.1, 0.40045], [1591.5, 1.302], [159155, 2.2]]}
  hb: {kind: soft, bh_file: hb.csv}
  bh: {kind: soft, bh_file: bh.csv}
  plain: {kind: soft, bh_file: plain.csv}
  lib: {library: steel_1010, bh_file: plain.csv}
)");
  const auto m = parse_case(dir / "case.yaml");
  for (const char* name : {"hb", "bh", "plain", "lib"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(m.at(name).curve);
    expect_identical(*m.at("inline").curve, *m.at(name).curve);
  }
}

// What write_bh_table_file writes (every library curve) reads back as the same curve.
TEST(BhTableFile, WrittenTableReadsBackBitForBit) {
  const auto dir = test_dir("round_trip");
  for (const auto& name : MaterialLibrary::bundled().names()) {
    const auto& curve = MaterialLibrary::bundled().find(name)->curve;
    if (!curve)
      continue;
    SCOPED_TRACE(name);
    std::ofstream out(dir / (name + ".csv"));
    magfem::write_bh_table_file(out, *curve);
    out.close();
    write(dir / "case.yaml", "materials:\n  again: {kind: soft, bh_file: " + name + ".csv}\n");
    expect_identical(*curve, *parse_case(dir / "case.yaml").at("again").curve);
  }
}

TEST(BhTableFile, SwappedColumnsAreRefusedInlineAndFromAFile) {
  const auto dir = test_dir("swapped");
  write(dir / "swapped.csv", "H_Apm,B_T\n0.2003,238.7\n0.40045,358.1\n1.302,1591.5\n");
  write(dir / "case.yaml", "materials:\n  iron:\n    kind: soft\n    bh_file: swapped.csv\n");
  auto e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.file(), (dir / "swapped.csv").string());
  EXPECT_EQ(e.line(), 2);
  EXPECT_TRUE(says(e, "columns swapped? B must be in T and H in A/m, as [H, B]")) << e.what();
  EXPECT_TRUE(says(e, (dir / "case.yaml").string() + ":4")) << "names the case line: " << e.what();
  EXPECT_TRUE(says(e, "materials.iron.bh_file")) << e.what();

  write(dir / "case.yaml", "materials:\n  iron:\n    kind: soft\n    bh:\n      - [0.2003, 238.7]\n"
                           "      - [0.40045, 358.1]\n");
  e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.field(), "materials.iron.bh[0]");
  EXPECT_TRUE(says(e, "columns swapped? B must be in T and H in A/m, as [H, B]")) << e.what();
}

TEST(BhTableFile, NonMonotoneAndShallowTablesInAFileNameTheLine) {
  const auto dir = test_dir("bad_rows");
  write(dir / "wiggle.csv", "H_Apm,B_T\n100,0.5\n300,1.2\n\n1000,1.1\n");
  write(dir / "shallow.csv", "100,0.5\n1000,1.5\n1e6,1.6\n");
  write(dir / "case.yaml", "materials:\n  a: {kind: soft, bh_file: wiggle.csv}\n");
  auto e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.file(), (dir / "wiggle.csv").string());
  EXPECT_EQ(e.line(), 5);
  EXPECT_TRUE(says(e, "not monotone")) << e.what();
  write(dir / "case.yaml", "materials:\n  a: {kind: soft, bh_file: shallow.csv}\n");
  e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.line(), 3);
  EXPECT_TRUE(says(e, "final slope dB/dH")) << e.what();
}

TEST(BhTableFile, MalformedFilesNameTheFileLineAndColumn) {
  const auto dir = test_dir("malformed");
  const auto error_for = [&](const std::string& csv) {
    write(dir / "t.csv", csv);
    write(dir / "case.yaml", "materials:\n  a: {kind: soft, bh_file: t.csv}\n");
    return case_error(dir / "case.yaml");
  };
  auto e = error_for("H,B\n100,0.5\n1000,1.5\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_TRUE(says(e, "H_Apm and B_T")) << e.what();
  e = error_for("B_T,H_Apm\n0.5,100\n1.5,1e3x\n");
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "H_Apm");
  e = error_for("100,0.5\n1000;1.5\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_TRUE(says(e, "2 comma-separated columns")) << e.what();
  e = error_for("H_Apm,B_T\n100,0.5\n");
  EXPECT_TRUE(says(e, "at least 2 rows")) << e.what();
}

TEST(BhTableFile, CaseFileMistakesNameTheCaseLineAndField) {
  const auto dir = test_dir("case_errors");
  write(dir / "case.yaml", "materials:\n  a:\n    kind: soft\n    bh_file: missing.csv\n");
  auto e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.file(), (dir / "case.yaml").string());
  EXPECT_EQ(e.line(), 4);
  EXPECT_EQ(e.field(), "materials.a.bh_file");
  EXPECT_TRUE(says(e, (dir / "missing.csv").string())) << e.what();

  write(dir / "t.csv", "100,0.5\n1000,1.5\n");
  write(
      dir / "case.yaml",
      "materials:\n  a:\n    kind: soft\n    bh: [[100, 0.5], [1000, 1.5]]\n    bh_file: t.csv\n");
  e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.line(), 5);
  EXPECT_TRUE(says(e, "not both")) << e.what();

  write(dir / "case.yaml", "materials:\n  a: {kind: soft}\n");
  e = case_error(dir / "case.yaml");
  EXPECT_EQ(e.field(), "materials.a");
  EXPECT_TRUE(says(e, "bh_file")) << e.what();
}
