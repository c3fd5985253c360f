// Ctrl-C and kill during a run (core/interrupt.hpp): the binary exits with the shell's code
// for the signal (130 for SIGINT, 143 for SIGTERM), says so, and leaves no outputs: no
// sweep.csv or summary.json, no staging folder, not even the output directory it created.
// The signal goes to an axisymmetric sweep of 61 remeshed positions after the first one is
// reported, while meshing and solving are under way.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "case_helpers.hpp"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int exit_code = -1;
  std::string stderr_text;
};

Outcome interrupt_sweep(int sig, const fs::path& out) {
  fs::remove_all(out);
  const fs::path err = out.string() + ".stderr";
  const std::string case_file = magfem::test::example("axi/voice_coil_magnet.yaml");
  fs::remove(err);
  const pid_t pid = fork();
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 2);
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    execl(MAGFEM_BINARY, MAGFEM_BINARY, "sweep", case_file.c_str(), "--move", "coil", "--axis", "z",
          "--positions", "0:0.2:12", "--jobs", "1", "--out", out.c_str(), nullptr);
    _exit(127);
  }
  // The first progress line means the handler is installed and the sweep is working (a
  // signal before main() would kill the process instead); 60 positions are still to come.
  const auto t0 = std::chrono::steady_clock::now();
  auto text_of = [](const fs::path& p) {
    std::stringstream s;
    s << std::ifstream(p).rdbuf();
    return s.str();
  };
  while (text_of(err).find("position") == std::string::npos &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, sig);
  int status = 0;
  waitpid(pid, &status, 0);
  Outcome o;
  if (WIFEXITED(status))
    o.exit_code = WEXITSTATUS(status);
  o.stderr_text = text_of(err);
  return o;
}

void expect_nothing_written(const fs::path& out) {
  if (!fs::exists(out))
    return; // the sweep created it, and it went with the rest
  for (const auto& f : fs::directory_iterator(out))
    ADD_FAILURE() << "left behind: " << f.path();
}

} // namespace

TEST(Interrupt, SigintDuringASweepExits130AndLeavesNoOutputs) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "interrupt_int";
  fs::create_directories(out.parent_path());
  const auto o = interrupt_sweep(SIGINT, out);
  EXPECT_EQ(o.exit_code, 130) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("interrupted by SIGINT"), std::string::npos) << o.stderr_text;
  expect_nothing_written(out);
}

TEST(Interrupt, SigtermDuringASweepExits143AndLeavesNoOutputs) {
  const fs::path out = fs::temp_directory_path() / "magfem_tests" / "interrupt_term";
  fs::create_directories(out.parent_path());
  const auto o = interrupt_sweep(SIGTERM, out);
  EXPECT_EQ(o.exit_code, 143) << o.stderr_text;
  EXPECT_NE(o.stderr_text.find("interrupted by SIGTERM"), std::string::npos) << o.stderr_text;
  expect_nothing_written(out);
}
