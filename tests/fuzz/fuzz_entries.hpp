#pragma once
// What each fuzz target does with one input, shared by the libFuzzer executables
// (fuzz_*.cpp, built with -DMAGFEM_FUZZ=ON) and the default-suite replay of the regression
// inputs (test_fuzz_regressions.cpp, any compiler). Every input must end in a value or an
// InputError; anything else escapes (another exception, a crash, a sanitizer report) and is a
// finding. Accepted inputs are also checked for properties the later stages rely on; a
// violation throws std::logic_error.
#include <string_view>

namespace magfem::fuzz {

// YAML text -> read_case_text (every dimension: the text picks it).
void case_reader(std::string_view data);
// YAML text -> a material library document (root `materials:` map, as materials/library.yaml)
// or, for any other root, a B-H table [[H, B], ...]; an accepted curve must evaluate to finite,
// odd, mutually inverse B(H) and H(B).
void material_parser(std::string_view data);
// CSV text -> read_probe_csv, then compare_probes of the table with itself (all zeros).
void probe_csv(std::string_view data);

} // namespace magfem::fuzz
