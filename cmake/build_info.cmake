# Script mode (cmake -P), run at every build: writes the commit the binary is built from into
# OUTPUT, touching it only when the text changes so an unchanged tree relinks nothing.
# Inputs: SOURCE_DIR, OUTPUT, VERSION.
execute_process(COMMAND git rev-parse HEAD WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown")
else()
  # Tracked files edited since the commit: the result did not come from that commit alone.
  execute_process(COMMAND git status --porcelain --untracked-files=no
    WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE changes ERROR_QUIET)
  if(NOT changes STREQUAL "")
    string(APPEND commit "-dirty")
  endif()
endif()
set(text "// Generated at build time by cmake/build_info.cmake.\n\
namespace magfem::build_info {\n\
extern const char* const version;\n\
extern const char* const commit;\n\
const char* const version = \"${VERSION}\";\n\
const char* const commit = \"${commit}\";\n\
} // namespace magfem::build_info\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
else()
  set(old "")
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUTPUT} "${text}")
endif()
