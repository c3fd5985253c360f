#include "core/option_table.hpp"

#include <algorithm>

namespace magfem {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

} // namespace

std::string nearest_option(const std::string& typed, const std::vector<OptionInfo>& known) {
  // A third of the name (at least 2 edits) is a typo; more is another word.
  const std::size_t limit = std::max<std::size_t>(2, typed.size() / 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const auto& option : known) {
    const std::size_t d = edit_distance(typed, option.name);
    if (d < best_distance)
      best = option.name, best_distance = d;
  }
  return best;
}

void throw_option_error(const std::string& option, const std::string& message) {
  throw InputError("<command line>", 0, option, message);
}

} // namespace magfem
