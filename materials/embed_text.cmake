# cmake -DINPUT=<text file> -DOUTPUT=<.cpp> -P embed_text.cmake
# Writes a .cpp defining magfem::bundled_library_text() that returns the file's text as a raw
# string literal, so the binary carries its data and never reads the source tree.
file(READ "${INPUT}" content)
string(FIND "${content}" ")magfem_text\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )magfem_text\"")
endif()
set(text "// Generated from ${INPUT} by embed_text.cmake: do not edit.
#include \"materials/library_text.hpp\"

namespace magfem {

std::string_view bundled_library_text() {
  static constexpr char text[] = R\"magfem_text(${content})magfem_text\";
  return {text, sizeof(text) - 1};
}

} // namespace magfem
")
file(WRITE "${OUTPUT}" "${text}")
