// TetGen 1.5 (Debian's libtet1.5) failures, made recoverable.
//
// 1. Error codes. TetGen reports an error by calling terminatetetgen(m, code), which frees
//    the mesh's memory pools (m->freememory()) and throws the code. The tetgenmesh is a local
//    of tetrahedralize(): while the exception unwinds it, its destructor calls freememory()
//    again, the pools are deleted twice, and the process dies (SIGSEGV, or glibc's abort
//    "munmap_chunk(): invalid pointer") before the error reaches mesher3d.cpp's catch.
//    TetGen 1.6 fixed it by nulling the pointers. The library calls terminatetetgen through
//    its PLT (43 call sites, objdump), so this definition in the executable takes the
//    library's place (ELF symbol interposition): it only throws, and the destructor frees the
//    pools once.
// 2. Assertions. Debian builds TetGen with assert() on; a degenerate input can fail one
//    (measured: fillregion, "j >= 1", on two crossing triangles) and abort. While a
//    TetGenErrorScope is alive on the thread, __assert_fail throws TetGenAssertion instead;
//    everywhere else it is glibc's.
//
// This file must not include tetgen.h (terminatetetgen is defined inline there) nor
// <cassert> (which declares __assert_fail noexcept).
#include "mesh/tetgen_termination.hpp"

#include <dlfcn.h>

class tetgenmesh;

void terminatetetgen(tetgenmesh* /*mesh: freed by its destructor*/, int code) {
  throw code;
}

namespace {
thread_local int tetgen_depth = 0;
using AssertFail = void (*)(const char*, const char*, unsigned, const char*);
} // namespace

extern "C" [[noreturn]] void __assert_fail(const char* assertion, const char* file, unsigned line,
                                           const char* function) {
  if (tetgen_depth > 0)
    throw magfem::TetGenAssertion(std::string("assertion '") + assertion + "' failed (" + file +
                                  ":" + std::to_string(line) + ")");
  const auto real = reinterpret_cast<AssertFail>(dlsym(RTLD_NEXT, "__assert_fail"));
  real(assertion, file, line, function);
  __builtin_trap(); // glibc's does not return
}

namespace magfem {

// Referenced from mesher3d.cpp so that every program using the mesher links this file.
extern const int tetgen_termination_interposed = 1;

TetGenErrorScope::TetGenErrorScope() {
  ++tetgen_depth;
}
TetGenErrorScope::~TetGenErrorScope() {
  --tetgen_depth;
}

} // namespace magfem
