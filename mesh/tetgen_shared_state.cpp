// Interposes TetGen's exactinit and glibc's rand/srand (see tetgen_shared_state.hpp). Like
// tetgen_termination.cpp this file must not include tetgen.h; the executable's definitions
// take the library's place through ELF symbol interposition, and every other caller of rand
// gets glibc's through dlsym(RTLD_NEXT).
#include "mesh/tetgen_shared_state.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <dlfcn.h>

// TetGen 1.5's predicates.cxx: exactinit(verbose, noexact, nofilter, maxx, maxy, maxz), where
// max* are the extents of the input's bounding box.
void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz);

namespace {

using ExactInit = void (*)(int, int, int, double, double, double);
using Rand = int (*)();
using Srand = void (*)(unsigned);

std::atomic<bool> filters_pinned{false};
std::atomic<long> n_ignored{0};

ExactInit real_exactinit() {
  // The mangled name of exactinit(int, int, int, double, double, double).
  return reinterpret_cast<ExactInit>(dlsym(RTLD_NEXT, "_Z9exactinitiiiddd"));
}

// glibc's rand state size for its default generator (TYPE_3, 31 words plus the type word).
constexpr int rand_state_bytes = 128;

struct PieceRandom {
  bool active = false;
  random_data data{};
  char state[rand_state_bytes]{};

  void seed(unsigned s) {
    data = {};
    initstate_r(s, state, sizeof state, &data);
  }
};
thread_local PieceRandom piece_random;
thread_local long piece_draws = 0; // rand() calls answered by piece_random on this thread

} // namespace

void exactinit(int verbose, int noexact, int nofilter, double maxx, double maxy, double maxz) {
  if (filters_pinned.load()) {
    ++n_ignored;
    return;
  }
  real_exactinit()(verbose, noexact, nofilter, maxx, maxy, maxz);
}

extern "C" int rand() noexcept {
  static const auto real = reinterpret_cast<Rand>(dlsym(RTLD_NEXT, "rand"));
  if (!piece_random.active)
    return real();
  ++piece_draws;
  std::int32_t r = 0;
  random_r(&piece_random.data, &r);
  return r;
}

extern "C" void srand(unsigned seed) noexcept {
  static const auto real = reinterpret_cast<Srand>(dlsym(RTLD_NEXT, "srand"));
  if (!piece_random.active) {
    real(seed);
    return;
  }
  piece_random.seed(seed);
}

namespace magfem {

TetGenSharedFilters::TetGenSharedFilters(double dx, double dy, double dz)
    : dx_(dx), dy_(dy), dz_(dz) {
  // TetGen's own call with -Q and default exactness: verbose 0, noexact 0, nofilter 0.
  real_exactinit()(0, 0, 0, dx, dy, dz);
  filters_pinned.store(true);
}

TetGenSharedFilters::~TetGenSharedFilters() {
  filters_pinned.store(false);
}

long TetGenSharedFilters::ignored_calls() {
  return n_ignored.load();
}

bool TetGenSharedFilters::pinned_for_tetgen() const {
  // The pinned box itself: if the call reaches TetGen's own exactinit, nothing changes.
  const long before = ignored_calls();
  exactinit(0, 0, 0, dx_, dy_, dz_);
  return ignored_calls() > before;
}

bool TetGenPieceScope::reaches_tetgen() {
  const TetGenPieceScope probe;
  const long before = piece_draws;
  (void)std::rand();
  return piece_draws > before;
}

bool tetgen_calls_may_overlap(const TetGenSharedFilters& filters) {
  return filters.pinned_for_tetgen() && TetGenPieceScope::reaches_tetgen();
}

TetGenPieceScope::TetGenPieceScope() {
  piece_random.seed(1);
  piece_random.active = true;
}

TetGenPieceScope::~TetGenPieceScope() {
  piece_random.active = false;
}

} // namespace magfem
