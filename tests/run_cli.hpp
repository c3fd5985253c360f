#pragma once
// Runs the magfem binary with a command line, stdout and stderr together.
#include <array>
#include <cstdio>
#include <string>

#include "tests/test_paths.hpp"
#include <sys/wait.h>

namespace magfem::test {

struct CliOutcome {
  int status = -1; // exit code, -1 if killed by a signal
  std::string out; // stdout and stderr
};

// Runs a whole shell command line, stdout and stderr together.
inline CliOutcome run_command(const std::string& command) {
  const std::string cmd = command + " 2>&1";
  CliOutcome o;
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (pipe && fgets(buf.data(), buf.size(), pipe))
    o.out += buf.data();
  const int raw = pipe ? pclose(pipe) : -1;
  o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return o;
}

inline CliOutcome run_cli(const std::string& args) {
  return run_command(std::string(magfem::test::magfem_binary()) + " " + args);
}

} // namespace magfem::test
