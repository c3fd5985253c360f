#include "core/input_error.hpp"

namespace magfem {
namespace {
std::string format_location(const std::string& file, int line, const std::string& field,
                            const std::string& message) {
  std::string text = file.empty() ? std::string("<input>") : file;
  if (line > 0) text += ":" + std::to_string(line);
  text += ": ";
  if (!field.empty()) text += "field '" + field + "': ";
  return text + message;
}
} // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& message)
    : std::runtime_error(format_location(file, line, field, message)), file_(std::move(file)),
      line_(line), field_(std::move(field)), reason_(message) {}

} // namespace magfem
