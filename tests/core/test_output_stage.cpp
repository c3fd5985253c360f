#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/output_stage.hpp"

namespace fs = std::filesystem;

TEST(OutputStage, NothingIsLeftBehindWithoutCommit) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_abort";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    magfem::OutputStage stage(dir);
    stage.write_text("summary.json", "{}");
  }
  EXPECT_TRUE(fs::is_empty(dir) || !fs::exists(dir));
  fs::remove_all(dir);
}

TEST(OutputStage, CommitMovesFilesIntoPlace) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_commit";
  fs::remove_all(dir);
  fs::create_directories(dir);
  {
    magfem::OutputStage stage(dir);
    stage.write_text("a.csv", "x\n1\n");
    stage.commit();
  }
  EXPECT_TRUE(fs::exists(dir / "a.csv"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir))
    ++entries;
  EXPECT_EQ(entries, 2u); // a.csv and the manifest; the staging folder is gone
  EXPECT_TRUE(fs::exists(dir / magfem::OutputStage::manifest_name));
  fs::remove_all(dir);
}

namespace {

void write_run(const fs::path& dir, const std::vector<std::string>& names) {
  magfem::OutputStage stage(dir);
  for (const auto& n : names)
    stage.write_text(n, "run with " + std::to_string(names.size()) + " files\n");
  stage.commit();
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

} // namespace

// A rerun that writes fewer files (a probe dropped from the case) must not leave the old
// probe's CSV beside the new summary, where it would pass for a result of this run; files
// magfem did not write (the user's notes) are never touched.
TEST(OutputStage, RerunRemovesItsOwnStaleFilesAndNothingElse) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_rerun";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "notes.txt") << "mine\n";
  write_run(dir, {"old_probe.csv", "kept.csv", "summary.json"});
  ASSERT_TRUE(fs::exists(dir / "old_probe.csv"));
  write_run(dir, {"kept.csv", "summary.json"});
  EXPECT_FALSE(fs::exists(dir / "old_probe.csv"));
  EXPECT_EQ(read_text(dir / "kept.csv"), "run with 2 files\n");
  EXPECT_EQ(read_text(dir / "summary.json"), "run with 2 files\n");
  EXPECT_EQ(read_text(dir / "notes.txt"), "mine\n");
  EXPECT_EQ(read_text(dir / magfem::OutputStage::manifest_name), "kept.csv\nsummary.json\n");
  fs::remove_all(dir);
}

// A failed rerun leaves the previous complete run as it was, record included.
TEST(OutputStage, FailedRerunLeavesThePreviousRunWhole) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_failed_rerun";
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_run(dir, {"a.csv", "summary.json"});
  {
    magfem::OutputStage stage(dir);
    stage.write_text("a.csv", "half\n");
  } // no commit: the run failed
  EXPECT_EQ(read_text(dir / "a.csv"), "run with 2 files\n");
  EXPECT_EQ(read_text(dir / "summary.json"), "run with 2 files\n");
  fs::remove_all(dir);
}

// A manifest that names something outside the directory cannot make a commit delete it.
TEST(OutputStage, ManifestCannotReachOutsideTheDirectory) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_manifest";
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "sub" / "precious") << "x";
  std::ofstream(dir / magfem::OutputStage::manifest_name) << "sub/precious\n..\n.\n";
  write_run(dir, {"summary.json"});
  EXPECT_TRUE(fs::exists(dir / "sub" / "precious"));
  fs::remove_all(dir);
}

// The console's "wrote" line lists what the stage wrote: the record first, then the files in
// the order they were staged, never the manifest (3D solves forgot forces.csv when the line
// was a hand-kept list).
TEST(OutputStage, WrittenListsEveryFileTheRecordFirst) {
  const fs::path dir = fs::temp_directory_path() / "magfem_stage_written";
  fs::remove_all(dir);
  fs::create_directories(dir);
  magfem::OutputStage stage(dir);
  stage.write_text("probe.csv", "x\n1\n");
  stage.write_text("forces.csv", "name\nf\n");
  stage.write_text("summary.json", "{}");
  stage.commit();
  EXPECT_EQ(stage.written(), (std::vector<std::string>{"summary.json", "probe.csv", "forces.csv"}));
  fs::remove_all(dir);
}
