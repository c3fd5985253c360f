#include "validation/report_text.hpp"

#include <array>
#include <cctype>
#include <string_view>
#include <vector>

namespace magfem {

std::string html_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

namespace {

// Replaces paired `marker`s by open/close tags; a lone last marker is dropped, because a
// stray backtick on the page reads as a rendering bug.
std::string pair_markers(const std::string& s, std::string_view marker, const char* open,
                         const char* close) {
  std::vector<std::size_t> at;
  for (auto p = s.find(marker); p != std::string::npos; p = s.find(marker, p + marker.size()))
    at.push_back(p);
  std::string out;
  std::size_t from = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    out += s.substr(from, at[k] - from);
    if (k + 1 < at.size() || k % 2 == 1)
      out += k % 2 == 0 ? open : close;
    from = at[k] + marker.size();
  }
  return out + s.substr(from);
}

bool path_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '.' || c == '_' ||
         c == '-' || c == '+' || c == '~';
}

// Where an absolute path may start: not after a letter, digit or ')' ("A/m", "1/2" and
// "(a + b)/2" are not paths) and not after ':' (URLs keep their "//").
bool path_may_start(const std::string& s, std::size_t i) {
  if (s[i] != '/' || i + 1 >= s.size() || !std::isalnum(static_cast<unsigned char>(s[i + 1])))
    return false;
  if (i == 0)
    return true;
  const char before = s[i - 1];
  return before == ' ' || before == '\t' || before == '\n' || before == '\'' || before == '"' ||
         before == '(' || before == '=' || before == ',' || before == '[';
}

// "/tmp/x/examples/3d/a.yaml" -> "examples/3d/a.yaml"; "/tmp/run/err.txt" -> "err.txt".
std::string strip_machine_part(const std::string& path) {
  static const std::array<const char*, 7> project_folders = {
      "examples", "validation", "docs", "materials", "tests", "scripts", "python"};
  std::vector<std::string> parts;
  std::size_t from = 1;
  for (auto p = path.find('/', from);; p = path.find('/', from)) {
    parts.push_back(path.substr(from, p - from));
    if (p == std::string::npos)
      break;
    from = p + 1;
  }
  for (std::size_t k = 0; k + 1 < parts.size(); ++k)
    for (const char* folder : project_folders)
      if (parts[k] == folder) {
        std::string out = parts[k];
        for (std::size_t j = k + 1; j < parts.size(); ++j)
          out += "/" + parts[j];
        return out;
      }
  return parts.back();
}

} // namespace

std::string html_text(const std::string& s) {
  return pair_markers(pair_markers(html_escape(s), "`", "<code>", "</code>"), "**", "<b>", "</b>");
}

std::string project_relative(const std::string& text, const std::string& root) {
  std::string s = text;
  if (!root.empty()) {
    const std::string prefix = root.back() == '/' ? root : root + "/";
    for (auto p = s.find(prefix); p != std::string::npos; p = s.find(prefix, p))
      s.erase(p, prefix.size());
  }
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (!path_may_start(s, i)) {
      out += s[i++];
      continue;
    }
    std::size_t end = i;
    while (end < s.size() && path_char(s[end]))
      ++end;
    const std::string path = s.substr(i, end - i);
    // One component ("/s", "/m") is a unit or a ratio, not a path of the machine.
    out += path.find('/', 1) == std::string::npos ? path : strip_machine_part(path);
    i = end;
  }
  return out;
}

std::string readable_reason(const std::string& reason, const std::string& section) {
  static const std::string label = "paper_targets";
  std::string out;
  std::size_t from = 0;
  for (auto p = reason.find(label); p != std::string::npos; p = reason.find(label, from)) {
    out += reason.substr(from, p - from);
    std::size_t q = p + label.size();
    if (reason.compare(q, 3, ".md") == 0)
      q += 3;
    const bool lettered =
        q + 1 < reason.size() && reason[q] == ' ' &&
        std::isupper(static_cast<unsigned char>(reason[q + 1])) &&
        (q + 2 == reason.size() || !std::isalnum(static_cast<unsigned char>(reason[q + 2])));
    out += lettered ? "target for " + section : std::string("magfem's target list");
    from = lettered ? q + 2 : q;
  }
  return out + reason.substr(from);
}

std::string short_quantity(const std::string& quantity, std::size_t max_chars) {
  std::string s = quantity;
  // A closing parenthetical is a detail ("(FE)", "(exact fields of ...)"): the entry has it.
  if (!s.empty() && s.back() == ')') {
    const auto open = s.rfind(" (");
    if (open != std::string::npos && open > 0)
      s.erase(open);
  }
  if (s.size() <= max_chars)
    return s;
  auto cut = s.rfind(' ', max_chars);
  if (cut == std::string::npos || cut < max_chars / 2)
    cut = max_chars;
  s.erase(cut);
  while (!s.empty() && (s.back() == ',' || s.back() == ' '))
    s.pop_back();
  return s + "\u2026";
}

} // namespace magfem
