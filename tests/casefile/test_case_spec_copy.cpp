// CaseSpec's copy: a region's `material` points into its case's `materials`, and a copy must
// point into its own, or it dangles once the original is gone. The adaptive 3D solve copies
// the case for each pass (new mesh sizes) and wrote its VTU from such a copy after the
// original's end: a crash that depended on the heap's layout (the long tier's schema check
// saw it, a hand run did not).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "casefile/case_spec.hpp"

using namespace magfem;

namespace {

const char* const two_materials = R"(
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.05}
  steel: {kind: linear, mu_r: 800}
regions:
  - {name: magnet, shape: box, size: [5, 5, 5], material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}}
  - {name: ball, shape: box, size: [3, 3, 3], material: steel,
     placement: {translate: [0, 0, 12]}}
boundary: {type: open, radius: 40}
mesh: {size: 5}
)";

TEST(CaseSpecCopy, ACopysRegionsUseTheCopysMaterials) {
  auto original = std::make_unique<CaseSpec>(read_case_text(two_materials, "copy.yaml"));
  ASSERT_EQ(original->regions.size(), 2u);
  ASSERT_EQ(original->regions[0].material, &original->materials.at("pm"));
  const CaseSpec copy = *original;
  CaseSpec assigned;
  assigned = *original;
  original.reset(); // the copies must not need it
  for (const CaseSpec* c : {&copy, static_cast<const CaseSpec*>(&assigned)}) {
    EXPECT_EQ(c->regions[0].material, &c->materials.at("pm"));
    EXPECT_EQ(c->regions[1].material, &c->materials.at("steel"));
    EXPECT_DOUBLE_EQ(c->regions[1].material->mu_r, 800); // readable: the copy's own
  }
}

TEST(CaseSpecCopy, AMoveKeepsThePointersValid) {
  CaseSpec original = read_case_text(two_materials, "move.yaml");
  const Material* pm = original.regions[0].material;
  const CaseSpec moved = std::move(original);
  EXPECT_EQ(moved.regions[0].material, pm); // the map's nodes moved with it
  EXPECT_EQ(moved.regions[0].material, &moved.materials.at("pm"));
}

} // namespace
