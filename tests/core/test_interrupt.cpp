// core/interrupt: a signal while outputs are staged removes them (and the output directory
// the stage created) and exits 128 + signal. Run in a forked child, since the process exits.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "core/interrupt.hpp"
#include "core/output_stage.hpp"

namespace fs = std::filesystem;

namespace {

// Exit code of a child that stages `name` in `out`, then receives `sig`; -1 if it did not
// exit normally (killed by the signal: the handler was not in place).
int stage_then_signal(const fs::path& out, int sig, bool commit_first) {
  const pid_t pid = fork();
  if (pid == 0) {
    magfem::install_interrupt_handler();
    magfem::OutputStage stage(out);
    stage.write_text("field.csv", "x,Bx\n0,1\n");
    stage.write_text("summary.json", "{}");
    if (commit_first)
      stage.commit();
    kill(getpid(), sig);
    std::this_thread::sleep_for(std::chrono::seconds(20)); // the handler thread exits first
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST(Interrupt, SignalRemovesStagedOutputsAndTheDirectoryTheStageCreated) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "interrupt_stage";
  fs::remove_all(out);
  fs::create_directories(out.parent_path());
  EXPECT_EQ(stage_then_signal(out, SIGINT, false), 130);
  EXPECT_FALSE(fs::exists(out)); // created by the stage, empty once the staging went
  EXPECT_EQ(stage_then_signal(out, SIGTERM, false), 143);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Interrupt, CommittedOutputsStayAndNothingElseIsLeft) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "interrupt_committed";
  fs::remove_all(out);
  fs::create_directories(out);
  EXPECT_EQ(stage_then_signal(out, SIGINT, true), 130);
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_TRUE(fs::exists(out / "field.csv"));
  for (const auto& f : fs::directory_iterator(out))
    EXPECT_EQ(f.path().filename().string().rfind(".magfem-staging", 0), std::string::npos)
        << f.path();
}
