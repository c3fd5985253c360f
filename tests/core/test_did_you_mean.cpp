// closest_name: the suggestion of "did you mean" in error messages. Exact cases: what a slip
// is (one or two edits, case, hyphens) and what is too far to suggest.
#include <gtest/gtest.h>

#include "core/did_you_mean.hpp"

namespace magfem {

TEST(DidYouMean, SuggestsTheNearestNameWithinAFewEdits) {
  const std::vector<std::string> keys = {"magnetization", "material", "mesh_size", "name"};
  EXPECT_EQ(closest_name("magnetisation", keys), "magnetization"); // one substitution
  EXPECT_EQ(closest_name("matreial", keys), "material");           // one swap
  EXPECT_EQ(closest_name("MESH-SIZE", keys), "mesh_size");         // case and separators
  EXPECT_EQ(closest_name("nmae", keys), "name");
  EXPECT_EQ(closest_name("M19", {"M-19", "N42", "steel_1010"}), "M-19");
  EXPECT_EQ(closest_name("n42", {"M-19", "N42"}), "N42");
  // Too far: no suggestion rather than a wrong one.
  EXPECT_EQ(closest_name("colour", keys), "");
  EXPECT_EQ(closest_name("xyz", {"N42", "M-19"}), "");
  EXPECT_EQ(did_you_mean("magnetisation", keys), " (did you mean 'magnetization'?)");
  EXPECT_EQ(did_you_mean("colour", keys), "");
}

} // namespace magfem
