#include "studies/position_mesh_warnings.hpp"

#include <cstdio>
#include <regex>

namespace magfem {
namespace {

// The warning with its figures masked: what positions' warnings of one kind share.
std::string kind_of(const std::string& warning) {
  static const std::regex number(R"([-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
  return std::regex_replace(warning, number, "#");
}

std::string figure(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

struct Kind {
  std::string kind, first_text;
  std::vector<double> at;
  bool same_text = true;
};

// Up to six positions listed, else the first and the last with the count.
std::string where(const std::string& key, const Kind& k, std::size_t n_positions) {
  std::string s = key + " ";
  constexpr std::size_t listed = 6;
  if (k.at.size() <= listed) {
    for (std::size_t i = 0; i < k.at.size(); ++i)
      s += (i ? ", " : "") + figure(k.at[i]);
  } else {
    s += figure(k.at.front()) + " ... " + figure(k.at.back());
  }
  s += " (" + std::to_string(k.at.size()) + " of " + std::to_string(n_positions) + " positions";
  if (!k.same_text)
    s += "; the figures are those at " + figure(k.at.front());
  return s + ")";
}

} // namespace

std::vector<std::string>
grouped_mesh_warnings(const std::string& key,
                      const std::vector<std::pair<double, std::vector<std::string>>>& positions) {
  std::vector<Kind> kinds;
  for (const auto& [at, warnings] : positions)
    for (const std::string& w : warnings) {
      const std::string kind = kind_of(w);
      auto k = kinds.begin();
      while (k != kinds.end() && k->kind != kind)
        ++k;
      if (k == kinds.end()) {
        kinds.push_back({kind, w, {}, true});
        k = kinds.end() - 1;
      }
      if (k->at.empty() || k->at.back() != at)
        k->at.push_back(at);
      k->same_text = k->same_text && w == k->first_text;
    }
  std::vector<std::string> out;
  for (const Kind& k : kinds)
    out.push_back(where(key, k, positions.size()) + ": " + k.first_text);
  return out;
}

} // namespace magfem
