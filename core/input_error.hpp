#pragma once
// Errors a user can cause (bad case file, bad table, bad option). They carry the file, the
// 1-based line and the dotted field path so that every message points at the culprit.
// The CLI maps InputError to exit code 2.
#include <stdexcept>
#include <string>

namespace magfem {

class InputError : public std::runtime_error {
public:
  InputError(std::string file, int line, std::string field, const std::string& message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }
  // The bare message without the location prefix.
  const std::string& reason() const { return reason_; }

private:
  std::string file_;
  int line_;
  std::string field_;
  std::string reason_;
};

// Solver outcomes a user must hear about (no convergence, singular system): exit code 3.
class SolveError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace magfem
