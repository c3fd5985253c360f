// The console's unknowns are those of the system solved (the DOFs with the outer boundary's
// phi = 0 taken out), in the progress line and the solve line alike; the solve line names the
// other count DOFs, as summary.json's `unknowns`, and summary.json's `free_unknowns` is the
// console's count (issue 34 item 9: 92090 against 92740 read as a contradiction). Checked on a
// coarse order-1 sphere in open space, where the constrained DOFs are exactly the vertices of
// the mesh's outer boundary, found here from the faces that belong to one tetrahedron only.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <regex>
#include <set>

#include "casefile/case_spec.hpp"
#include "core/progress.hpp"
#include "pipeline/run3d.hpp"
#include "tests/case_helpers.hpp"

namespace magfem {
namespace {

struct Captured : Progress {
  std::vector<std::string> stages;
  Captured() : Progress(nullptr) {}
  void stage(const std::string& what) override { stages.push_back(what); }
  void iteration(const char*, int, double) override {}
  void note(const std::string&) override {}
};

TEST(FreeUnknowns, ProgressCountsTheDofsLessTheOuterBoundarysVertices) {
  Captured progress;
  RunOverrides overrides;
  overrides.progress = &progress;
  const auto run = run_case_3d(read_case_text(test::magnetized_sphere_case3d("5") + R"(
boundary: {type: open, radius: 25, shell_ratio: 1.5}
mesh: {size: 10}
solver: {order: 1}
)",
                                              "free_unknowns.yaml"),
                               overrides);
  std::map<std::array<int, 3>, int> faces;
  for (const auto& t : run->mesh.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip)
          f[static_cast<std::size_t>(j++)] = t[static_cast<std::size_t>(k)];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  std::set<int> outer;
  for (const auto& [f, count] : faces)
    if (count == 1)
      outer.insert(f.begin(), f.end());
  ASSERT_GT(outer.size(), 20u);
  const int free = run->dofs->n_dofs() - static_cast<int>(outer.size());

  const std::regex counted(R"(, (\d+) unknowns$)");
  int lines = 0;
  for (const auto& s : progress.stages) {
    std::smatch m;
    if (!std::regex_search(s, m, counted))
      continue;
    ++lines;
    EXPECT_EQ(std::stoi(m[1]), free) << s;
  }
  EXPECT_EQ(lines, 1) << "the set-up or factorization line";
  const auto summary = summary_json_3d(*run);
  EXPECT_EQ(summary.at("unknowns").get<int>(), run->dofs->n_dofs());
  EXPECT_EQ(summary.at("free_unknowns").get<int>(), free);
  const std::string solve_line = "solve    order 1, " + std::to_string(free) + " unknowns (" +
                                 std::to_string(run->dofs->n_dofs()) + " DOFs, " +
                                 std::to_string(outer.size()) + " fixed)";
  EXPECT_NE(describe_run_3d(*run).find(solve_line), std::string::npos) << describe_run_3d(*run);
}

} // namespace
} // namespace magfem
