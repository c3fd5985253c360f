#include <gtest/gtest.h>

#include "core/yaml_node.hpp"

using magfem::InputError;
using magfem::YamlNode;

TEST(YamlNode, ReportsLineAndFieldOfABadNumber) {
  const auto root = YamlNode::load_string("a: 1\nb:\n  c: abc\n", "case.yaml");
  try {
    root.at("b").at("c").as_double();
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.yaml");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.field(), "b.c");
  }
}

TEST(YamlNode, MissingFieldNamesTheParentLineAndTheField) {
  const auto root = YamlNode::load_string("a: 1\nb:\n  c: 2\n", "case.yaml");
  try {
    root.at("b").at("d");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "b.d");
    EXPECT_EQ(e.line(), 3);
  }
}

TEST(YamlNode, UnknownKeyIsRejectedWithItsLine) {
  const auto root = YamlNode::load_string("a: 1\nbogus: 2\n", "case.yaml");
  try {
    root.allow_keys({"a"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "bogus");
    EXPECT_EQ(e.line(), 2);
  }
}

// Found by fuzzing: yaml-cpp's own conversion exception escaped as an internal error (exit 1).
TEST(YamlNode, AKeyThatIsNotTextIsAnInputErrorAtItsLine) {
  const auto root = YamlNode::load_string("a: 1\n? [b, c]\n: 2\n", "case.yaml");
  for (const auto& call : {+[](const YamlNode& n) { n.allow_keys({"a"}); },
                           +[](const YamlNode& n) { (void)n.keys(); }}) {
    try {
      call(root);
      FAIL();
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 2) << e.what();
      EXPECT_NE(e.reason().find("plain text"), std::string::npos) << e.what();
    }
  }
}

TEST(YamlNode, MalformedYamlGivesTheParserLine) {
  try {
    YamlNode::load_string("a: 1\nb: [1, 2\nc: 3\n", "bad.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.yaml");
    EXPECT_GE(e.line(), 2);
  }
}

TEST(YamlNode, PositiveAndSequenceChecks) {
  const auto root = YamlNode::load_string("size: -1\nv: [1, 2]\n", "x.yaml");
  EXPECT_THROW(root.at("size").as_positive(), InputError);
  EXPECT_THROW(root.at("v").as_doubles(3), InputError);
  EXPECT_EQ(root.at("v").as_doubles(2).size(), 2u);
}
