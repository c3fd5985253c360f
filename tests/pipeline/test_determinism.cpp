// Determinism (issue 15): the same case gives bitwise-identical summary.json numbers and probe
// CSVs from run to run, and across thread counts within a stated relative tolerance.
//
// Run to run: every parallel loop sums each entry in element order whatever the schedule
// (core/parallel_scatter.hpp), the mesher and CHOLMOD are sequential, so the bits must agree;
// a race, an uninitialized value or an unordered container iterated into the results would
// break it. Across thread counts (MAGFEM_THREADS and OPENBLAS_NUM_THREADS 1 against 2): the
// assembly and B recovery are bitwise thread-count independent by construction, but OpenBLAS
// may split its kernels by thread count; such sums differ in their last bits, a relative 1e-16 per
// operation. Stated tolerance: 1e-12 relative to the largest value of the same quantity
// (10^4 ulps of headroom); measured: see docs/reliability.md.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "tests/case_helpers.hpp"
#include "tests/test_paths.hpp"

namespace fs = std::filesystem;

namespace {

// Keys whose values are measurements of the run, not results.
const std::set<std::string> not_results = {
    "timings_s", "peak_memory_MB", "magfem_version", "magfem_commit", "case", "seconds", "threads"};

// threads: magfem's own (MAGFEM_THREADS); blas_threads: OpenBLAS's (0: the same).
int solve(const std::string& case_file, const fs::path& out, int threads, int blas_threads = 0,
          const std::string& options = "") {
  fs::remove_all(out);
  const std::string cmd =
      "MAGFEM_THREADS=" + std::to_string(threads) +
      " OPENBLAS_NUM_THREADS=" + std::to_string(blas_threads > 0 ? blas_threads : threads) + " " +
      magfem::test::magfem_binary() + " solve " + case_file + " " + options + " --quiet --out " +
      out.string() + " > " + out.string() + ".log 2>&1";
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string text_of(const fs::path& p) {
  std::stringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

// The numbers of a JSON document in document order, each with its path without array
// indices ("forces.force"), which names the quantity; keys in not_results are left out.
void flatten(const nlohmann::json& j, const std::string& path,
             std::vector<std::pair<std::string, double>>& out) {
  if (j.is_number())
    out.emplace_back(path, j.get<double>());
  else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!not_results.count(it.key()))
        flatten(it.value(), path + "." + it.key(), out);
  } else if (j.is_array())
    for (const auto& v : j)
      flatten(v, path, out);
  else
    out.emplace_back(path + "=" + j.dump(), 0.0); // strings, booleans: must match exactly
}

// Largest difference between corresponding numbers relative to the largest magnitude of
// the same quantity (path, or CSV column): a component that is zero up to round-off is
// judged against the field's size, not against its own noise.
double max_relative_difference(const std::vector<std::pair<std::string, double>>& a,
                               const std::vector<std::pair<std::string, double>>& b) {
  if (a.size() != b.size()) {
    ADD_FAILURE() << "different numbers of values: " << a.size() << " and " << b.size();
    return 1;
  }
  std::map<std::string, double> scale;
  for (const auto& [path, v] : a)
    scale[path] = std::max(scale[path], std::abs(v));
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].first != b[i].first) {
      ADD_FAILURE() << a[i].first << " against " << b[i].first;
      return 1;
    }
    if (a[i].second != b[i].second)
      worst = std::max(worst,
                       std::abs(a[i].second - b[i].second) / std::max(scale[a[i].first], 1e-300));
  }
  return worst;
}

std::vector<std::pair<std::string, double>> json_numbers(const fs::path& file) {
  std::vector<std::pair<std::string, double>> out;
  flatten(nlohmann::json::parse(text_of(file)), "", out);
  return out;
}

// A CSV's numbers by column (header name); a non-number cell must match exactly.
std::vector<std::pair<std::string, double>> csv_numbers(const fs::path& file) {
  std::stringstream in(text_of(file));
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream h(line); std::getline(h, cell, ',');)
    header.push_back(cell);
  std::vector<std::pair<std::string, double>> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (std::size_t c = 0; std::getline(row, cell, ','); ++c) {
      const std::string column = c < header.size() ? header[c] : "?";
      try {
        out.emplace_back(column, std::stod(cell));
      } catch (const std::exception&) {
        out.emplace_back(column + "=" + cell, 0.0);
      }
    }
  }
  return out;
}

struct Comparison {
  double summary = 0, probes = 0;
};

Comparison compare_runs(const fs::path& a, const fs::path& b) {
  Comparison c;
  c.summary =
      max_relative_difference(json_numbers(a / "summary.json"), json_numbers(b / "summary.json"));
  for (const auto& f : fs::directory_iterator(a))
    if (f.path().extension() == ".csv")
      c.probes = std::max(c.probes, max_relative_difference(csv_numbers(f.path()),
                                                            csv_numbers(b / f.path().filename())));
  return c;
}

fs::path dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "magfem_tests" / "determinism" / name;
  fs::create_directories(d.parent_path());
  return d;
}

} // namespace

// Two touching magnet boxes magnetized differently, order 1, ~37k tetrahedra: the threaded
// assembly and B recovery run on two threads (one per 20k elements), CHOLMOD's supernodes on
// OpenBLAS; a probe line through both boxes and a stress-tensor box around them. ~2 s a run.
TEST(Determinism, SameCaseTwiceIsBitwiseIdenticalAndThreadCountsAgreeTo1e12) {
  const std::string case_file =
      magfem::test::write_temp_case("determinism.yaml", R"(title: two boxes
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.05}
regions:
  - {name: lower, shape: box, size: [10, 10, 5], material: pm,
     magnetization: {type: parallel, direction: [0, 0, 1]}, mesh_size: 3}
  - {name: upper, shape: box, size: [10, 10, 5], material: pm, placement: {translate: [0, 0, 5]},
     magnetization: {type: parallel, direction: [1, 0, 1]}, mesh_size: 3}
boundary: {type: open, radius: 30, shell_ratio: 1.5}
mesh: {size: 8}
solver: {order: 1}
probes:
  - {name: axis, type: line, start: [0, 0, -12], end: [0, 0, 17], points: 59}
forces:
  - {name: both_f, type: box, center: [0, 0, 2.5], size: [14, 14, 12]}
)");
  const fs::path a = dir("a"), b = dir("b"), one = dir("one");
  ASSERT_EQ(solve(case_file, a, 2), 0) << text_of(a.string() + ".log");
  ASSERT_EQ(solve(case_file, b, 2), 0) << text_of(b.string() + ".log");
  const Comparison same = compare_runs(a, b);
  EXPECT_EQ(same.summary, 0.0) << "summary.json numbers differ between two identical runs";
  EXPECT_EQ(same.probes, 0.0) << "probe CSVs differ between two identical runs";
  for (const auto& f : fs::directory_iterator(a)) {
    if (f.path().extension() == ".csv") {
      EXPECT_EQ(text_of(f.path()), text_of(b / f.path().filename())) << f.path();
    }
  }

  ASSERT_EQ(solve(case_file, one, 1), 0) << text_of(one.string() + ".log");
  const Comparison threads = compare_runs(a, one);
  std::printf("1 vs 2 threads: summary %.3g, probes %.3g (relative)\n", threads.summary,
              threads.probes);
  EXPECT_LE(threads.summary, 1e-12);
  EXPECT_LE(threads.probes, 1e-12);
}

// magfem's own threads alone (OpenBLAS on one thread in both runs): a coil, a magnet, the
// coil's source-field table, its flux linkage and inductance, the Lorentz force. Every loop of
// magfem sums in an order fixed by the mesh (elements, or blocks of them), so 1 and 2 threads
// give the same bits. The linkage used to sum one partial per thread (last bits depending on
// the count); ~14k tetrahedra, so it runs on two threads. ~3 s a run.
TEST(Determinism, MagfemThreadCountDoesNotChangeOneBitOfACoilCase) {
  const std::string coil_case =
      std::string(magfem::test::source_dir()) + "/examples/3d/coil_and_magnet.yaml";
  const fs::path one = dir("coil_one"), two = dir("coil_two");
  const std::string options = "--order 1 --mesh-scale 2";
  ASSERT_EQ(solve(coil_case, one, 1, 1, options), 0) << text_of(one.string() + ".log");
  ASSERT_EQ(solve(coil_case, two, 2, 1, options), 0) << text_of(two.string() + ".log");
  const nlohmann::json summary = nlohmann::json::parse(text_of(two / "summary.json"));
  ASSERT_GT(summary["elements"].get<double>(), 10000) << "the linkage must run on two threads";
  ASSERT_TRUE(summary.contains("coils"));
  const Comparison threads = compare_runs(one, two);
  EXPECT_EQ(threads.summary, 0.0) << "summary.json numbers differ between 1 and 2 threads";
  EXPECT_EQ(threads.probes, 0.0) << "probe CSVs differ between 1 and 2 threads";
}
