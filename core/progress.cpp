#include "core/progress.hpp"

namespace magfem {
namespace {
double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
} // namespace

Progress::Progress(std::FILE* out, double interval_s)
    : out_(out), interval_s_(interval_s), start_(Clock::now()), stage_start_(start_),
      last_print_(start_) {}

void Progress::stage(const std::string& what) {
  stage_start_ = Clock::now();
  iterating_ = false;
  std::fprintf(out_, "[%7.1f s] %s\n", seconds(stage_start_ - start_), what.c_str());
  std::fflush(out_);
}

void Progress::iteration(const char* solver, int iteration, double relative_residual) {
  const auto now = Clock::now();
  if (!iterating_) {
    iterating_ = true;
    last_print_ = now;
    return;
  }
  if (seconds(now - last_print_) < interval_s_)
    return;
  last_print_ = now;
  std::fprintf(out_, "[%7.1f s]   %s iteration %d, relative residual %.3e\n", seconds(now - start_),
               solver, iteration, relative_residual);
  std::fflush(out_);
}

void Progress::note(const std::string& what) {
  std::fprintf(out_, "[%7.1f s]   %s\n", seconds(Clock::now() - start_), what.c_str());
  std::fflush(out_);
}

} // namespace magfem
