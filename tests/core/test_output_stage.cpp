#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u); // staging folder removed
  fs::remove_all(dir);
}
