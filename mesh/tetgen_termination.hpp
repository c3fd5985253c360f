#pragma once
// TetGen's failures as exceptions (see tetgen_termination.cpp): its error codes are thrown as
// int, and, while a TetGenErrorScope is alive on the calling thread, a failed assertion
// inside the library throws TetGenAssertion instead of aborting the process.
#include <stdexcept>
#include <string>

namespace magfem {

struct TetGenAssertion : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class TetGenErrorScope {
public:
  TetGenErrorScope();
  ~TetGenErrorScope();
  TetGenErrorScope(const TetGenErrorScope&) = delete;
  TetGenErrorScope& operator=(const TetGenErrorScope&) = delete;
};

} // namespace magfem
