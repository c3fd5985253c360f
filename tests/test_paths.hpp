#pragma once
// Where the tests find the source tree (examples, catalogue, corpora) and the magfem binary.
// Defined in a file generated per build tree (tests/CMakeLists.txt), so that no test object
// carries a checkout's path and ccache can share test objects between clones.

namespace magfem::test {

const char* source_dir();
const char* magfem_binary();

} // namespace magfem::test
