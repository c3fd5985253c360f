#pragma once
// The text of materials/library.yaml, embedded at build time (see materials/CMakeLists.txt and
// embed_text.cmake); the definition is generated into the build tree.
#include <string_view>

namespace magfem {

std::string_view bundled_library_text();

} // namespace magfem
