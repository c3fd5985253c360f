#pragma once
// Usage text: the overview (`magfem --help`) and one page per command (`magfem help COMMAND`,
// `magfem COMMAND --help`). The bash completion (scripts/magfem-completion.bash) offers the
// same commands and options; tests/install/check_completion.sh checks that the two agree (and both against the option tables).
#include <optional>
#include <string>
#include <vector>

namespace magfem {

std::string usage_overview();
// Names of the commands, in the order the overview lists them.
std::vector<std::string> command_names();
// The page for one command; nothing for an unknown command.
std::optional<std::string> command_usage(const std::string& command);

} // namespace magfem
