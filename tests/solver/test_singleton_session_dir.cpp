// Each MPI singleton gets a session directory of its own (solver/singleton_session_dir.hpp):
// the shared default made one of two processes starting at once fail in orte_init. The race
// itself is provoked by singleton_race.sh (label long).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include "solver/singleton_session_dir.hpp"

namespace magfem::petsc_module {
namespace {

namespace fs = std::filesystem;

// Runs a test with the environment variables it sets or unsets put back afterwards.
class SessionDirEnvironment : public ::testing::Test {
protected:
  void SetUp() override {
    for (const char* name : {"OMPI_MCA_orte_tmpdir_base", "OMPI_COMM_WORLD_SIZE", "TMPDIR"}) {
      const char* v = std::getenv(name);
      saved_.push_back({name, v ? std::optional<std::string>(v) : std::nullopt});
      unsetenv(name);
    }
    tmp_ = fs::temp_directory_path() / ("session_dir_test_" + std::to_string(getpid()));
    fs::create_directories(tmp_);
    setenv("TMPDIR", tmp_.c_str(), 1);
  }
  void TearDown() override {
    for (const auto& [name, value] : saved_)
      value ? (void)setenv(name.c_str(), value->c_str(), 1) : (void)unsetenv(name.c_str());
    fs::remove_all(tmp_);
  }
  fs::path tmp_;

private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

TEST_F(SessionDirEnvironment, ASingletonGetsItsOwnDirectoryRemovedAtTheEnd) {
  std::string first_path;
  {
    SingletonSessionDir first;
    first_path = first.path();
    ASSERT_FALSE(first_path.empty());
    EXPECT_EQ(fs::path(first_path).parent_path(), tmp_); // under TMPDIR
    EXPECT_TRUE(fs::is_directory(first_path));
    EXPECT_EQ(std::string(std::getenv("OMPI_MCA_orte_tmpdir_base")), first_path); // MPI reads it
    // Another process (a fresh environment) gets another directory.
    unsetenv("OMPI_MCA_orte_tmpdir_base");
    SingletonSessionDir other;
    EXPECT_NE(other.path(), first_path);
    fs::create_directories(fs::path(first_path) / "ompi.host.0" / "jf.0" / "1");
  }
  EXPECT_FALSE(fs::exists(first_path)); // removed with what Open MPI left in it
  EXPECT_TRUE(fs::is_empty(tmp_));
}

TEST_F(SessionDirEnvironment, UnderMpirunOrAUsersChoiceNothingIsCreated) {
  setenv("OMPI_COMM_WORLD_SIZE", "2", 1); // mpirun's daemon owns the session
  EXPECT_EQ(SingletonSessionDir().path(), "");
  unsetenv("OMPI_COMM_WORLD_SIZE");
  setenv("OMPI_MCA_orte_tmpdir_base", tmp_.c_str(), 1);
  EXPECT_EQ(SingletonSessionDir().path(), "");
  EXPECT_EQ(std::string(std::getenv("OMPI_MCA_orte_tmpdir_base")), tmp_.string());
  EXPECT_TRUE(fs::is_empty(tmp_));
}

} // namespace
} // namespace magfem::petsc_module
