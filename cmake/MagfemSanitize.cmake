# -DMAGFEM_SANITIZE=address,undefined instruments every target (ours, the tests, and the
# header-only third-party code they inline: Eigen, CGAL). Shared libraries from Debian stay
# uninstrumented; ASan still sees their heap through its malloc interposer.
if(MAGFEM_SANITIZE)
  # Any report fails the run: a sanitizer finding is a bug, not a warning to scroll past.
  set(magfem_sanitize_flags -fsanitize=${MAGFEM_SANITIZE} -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  add_compile_options(${magfem_sanitize_flags})
  # GCC 12 with ASan at -O1 warns "may be used uninitialized" inside libstdc++'s <regex>
  # (std::function moves in _NFA::_M_insert_subexpr_*): a known false positive of the
  # instrumented code, not seen in the Release build.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  add_link_options(${magfem_sanitize_flags})
  message(STATUS "magfem: sanitizers ${MAGFEM_SANITIZE}")
endif()
# Fuzz builds: coverage instrumentation for every library; the fuzz executables alone link
# libFuzzer's main (tests/fuzz/CMakeLists.txt).
if(MAGFEM_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
