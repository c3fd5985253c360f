// A commit cut short between two renames (power cut, SIGKILL) must never leave a set of
// outputs that looks whole but mixes two runs. The record (summary.json) is removed first and
// renamed into place last, so every cut leaves the whole old run, the whole new run or no
// record at all; and the next run cleans up whatever the cut one left.
// The cut is made real: this test binary interposes rename(3), which std::filesystem::rename
// calls, and ends a forked child at its k-th rename, for every k until the commit completes.
#include <gtest/gtest.h>

#include <dlfcn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/output_stage.hpp"

namespace fs = std::filesystem;

namespace {
int crash_at_rename = 0; // 0: never
int renames_seen = 0;
constexpr int crashed_exit_code = 77;
} // namespace

extern "C" int rename(const char* from, const char* to) noexcept {
  using Rename = int (*)(const char*, const char*);
  static const auto real = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "rename"));
  if (crash_at_rename > 0 && ++renames_seen == crash_at_rename)
    _exit(crashed_exit_code); // as abrupt as a power cut: no destructors, no clean-up
  return real(from, to);
}

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

void previous_run(const fs::path& dir) {
  magfem::OutputStage stage(dir);
  stage.write_text("a.csv", "old");
  stage.write_text("b.csv", "old");
  stage.write_text("summary.json", "old");
  stage.commit();
}

} // namespace

TEST(OutputStageCrash, ACommitCutShortLeavesNoRecordNeverAMixOfTwoRuns) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_crash";
  int cuts = 0;
  for (int k = 1; k < 50; ++k) {
    fs::remove_all(dir);
    previous_run(dir);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      crash_at_rename = k;
      magfem::OutputStage stage(dir);
      stage.write_text("a.csv", "new");
      stage.write_text("c.csv", "new");
      stage.write_text("summary.json", "new");
      stage.commit();
      _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 0) {
      // The commit completed: the new run, whole, and the old run's b.csv gone.
      EXPECT_EQ(read(dir / "summary.json"), "new");
      EXPECT_EQ(read(dir / "a.csv"), "new");
      EXPECT_EQ(read(dir / "c.csv"), "new");
      EXPECT_FALSE(fs::exists(dir / "b.csv"));
      break;
    }
    ASSERT_EQ(WEXITSTATUS(status), crashed_exit_code);
    ++cuts;
    if (fs::exists(dir / "summary.json")) {
      // Cut before anything of the old run was touched: the old run, whole and alone.
      EXPECT_EQ(read(dir / "summary.json"), "old") << "cut at rename " << k;
      EXPECT_EQ(read(dir / "a.csv"), "old") << "cut at rename " << k;
      EXPECT_EQ(read(dir / "b.csv"), "old") << "cut at rename " << k;
      EXPECT_FALSE(fs::exists(dir / "c.csv")) << "cut at rename " << k;
    }
    // A rerun into the directory the cut left behind works and is whole.
    {
      magfem::OutputStage stage(dir);
      stage.write_text("a.csv", "again");
      stage.write_text("summary.json", "again");
      stage.commit();
    }
    EXPECT_EQ(read(dir / "summary.json"), "again");
    EXPECT_EQ(read(dir / "a.csv"), "again");
    EXPECT_FALSE(fs::exists(dir / "c.csv")) << "a file of the cut run survived a whole rerun";
  }
  // The transition manifest, a.csv, c.csv, the final manifest and the record: five renames,
  // each cut once.
  EXPECT_EQ(cuts, 5);
  fs::remove_all(dir);
}
