#include "core/input_error.hpp"

namespace magfem {
namespace {
std::string format_location(const std::string& file, int line, const std::string& field,
                            const std::string& message) {
  std::string text = file.empty() ? std::string("<input>") : file;
  // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + std::string.
  if (line > 0)
    text.append(":").append(std::to_string(line));
  text.append(": ");
  if (!field.empty())
    text.append("field '").append(field).append("': ");
  return text.append(message);
}
} // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& message)
    : std::runtime_error(format_location(file, line, field, message)), file_(std::move(file)),
      line_(line), field_(std::move(field)), reason_(message) {}

} // namespace magfem
