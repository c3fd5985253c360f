// Replays every input a fuzzer once broke (tests/fuzz/regressions/<target>/) and the seed
// corpus (tests/fuzz/corpus/<target>/) through the readers of the normal build. Fails if an
// input ends in anything but a value or an InputError (e.g. a yaml-cpp exception escaping as
// an internal error, exit 1, instead of exit 2 naming the file) or breaks an invariant the
// fuzz entry checks; under scripts/sanitize.sh also on any memory error or undefined behaviour.
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/fuzz/fuzz_entries.hpp"
#include "tests/test_paths.hpp"

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Number of inputs replayed from the target's folders; each failure is reported by name.
int replay(const std::string& target, const std::function<void(std::string_view)>& entry) {
  int n = 0;
  for (const char* kind : {"regressions", "corpus"}) {
    const fs::path dir = fs::path(magfem::test::source_dir()) / "tests/fuzz" / kind / target;
    if (!fs::is_directory(dir))
      continue;
    for (const auto& f : fs::directory_iterator(dir)) {
      if (!f.is_regular_file())
        continue;
      ++n;
      const std::string data = read_bytes(f.path());
      EXPECT_NO_THROW(entry(data)) << f.path();
    }
  }
  return n;
}

} // namespace

TEST(FuzzRegressions, CaseReader) {
  EXPECT_GT(replay("case_reader", magfem::fuzz::case_reader), 10);
}

TEST(FuzzRegressions, MaterialParser) {
  EXPECT_GT(replay("material_parser", magfem::fuzz::material_parser), 2);
}

TEST(FuzzRegressions, ProbeCsv) {
  EXPECT_GT(replay("probe_csv", magfem::fuzz::probe_csv), 2);
}
