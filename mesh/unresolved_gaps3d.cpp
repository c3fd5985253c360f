#include "mesh/unresolved_gaps3d.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

namespace magfem {
namespace {

std::string quoted(const std::string& name) {
  return "'" + name + "'";
}

// "'a', 'b', 'c' and 29 more": the first few names, so that the line stays readable.
std::string some_names(const std::vector<std::string>& names) {
  constexpr std::size_t shown = 3;
  std::string out;
  for (std::size_t i = 0; i < std::min(shown, names.size()); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + quoted(names[i]);
  if (names.size() > shown)
    out += " and " + std::to_string(names.size() - shown) + " more";
  return out;
}

std::string advice(int order, int layers, double scale) {
  char text[300];
  std::snprintf(text, sizeof text,
                "their nodes (order %d) farther apart than %s wide (gap_layers %d, sizes "
                "scaled by %.3g in all: the case's mesh scale times --mesh-scale): the field in "
                "%s not resolved; scale the sizes by at most %d in all, or make the mesh size "
                "near %s smaller",
                order, "%GAP_IS%", layers, scale, "%FIELD%", order * layers, "%NEAR%");
  return text;
}

std::string replaced(std::string s, const std::string& what, const std::string& by) {
  s.replace(s.find(what), what.size(), by);
  return s;
}

std::string one_gap(const std::string& a, const std::string& b, const UnresolvedGap& gap,
                    const std::string& tail) {
  char text[200];
  std::snprintf(text, sizeof text,
                "the %.3g mm air gap between parts %s and %s has elements of about %.3g mm "
                "across it, ",
                gap.width * 1e3, quoted(a).c_str(), quoted(b).c_str(), gap.across * 1e3);
  return text +
         replaced(replaced(replaced(tail, "%GAP_IS%", "the gap is"), "%FIELD%", "the gap is"),
                  "%NEAR%", "the gap");
}

std::string gaps_of_one_part(const std::string& part, const std::vector<std::string>& others,
                             double narrowest, double widest, double across,
                             const std::string& tail) {
  char widths[80], size[40];
  if (narrowest == widest)
    std::snprintf(widths, sizeof widths, "%.3g mm", narrowest * 1e3);
  else
    std::snprintf(widths, sizeof widths, "%.3g to %.3g mm", narrowest * 1e3, widest * 1e3);
  std::snprintf(size, sizeof size, "%.3g", across * 1e3);
  return "the air gaps between part " + quoted(part) + " and " + std::to_string(others.size()) +
         " other parts (" + some_names(others) + "), " + widths +
         " wide, have elements of up to about " + size + " mm across them, " +
         replaced(replaced(replaced(tail, "%GAP_IS%", "the gaps are"), "%FIELD%", "these gaps is"),
                  "%NEAR%", "the gaps");
}

} // namespace

std::vector<std::string> unresolved_gap_warnings(const std::vector<std::string>& part_names,
                                                 int order, int gap_layers, double scale,
                                                 const UnresolvedGaps& unresolved) {
  const std::string tail = advice(std::max(1, order), std::max(1, gap_layers), scale);
  std::set<std::pair<int, int>> left;
  for (const auto& [pair, gap] : unresolved)
    if (gap.across > std::max(1, order) * gap.width)
      left.insert(pair);
  std::vector<std::string> out;
  const auto name = [&](int part) { return part_names[static_cast<std::size_t>(part)]; };
  // The part in the most gaps left takes them all into one warning, while it has two or more.
  while (!left.empty()) {
    std::map<int, int> gaps_of;
    for (const auto& [a, b] : left) {
      ++gaps_of[a];
      ++gaps_of[b];
    }
    const auto most = std::max_element(gaps_of.begin(), gaps_of.end(),
                                       [](auto x, auto y) { return x.second < y.second; });
    if (most->second < 2)
      break;
    const int part = most->first;
    std::vector<std::string> others;
    double narrowest = 1e300, widest = 0, across = 0;
    for (auto it = left.begin(); it != left.end();) {
      if (it->first != part && it->second != part) {
        ++it;
        continue;
      }
      const UnresolvedGap& gap = unresolved.at(*it);
      others.push_back(name(it->first == part ? it->second : it->first));
      narrowest = std::min(narrowest, gap.width);
      widest = std::max(widest, gap.width);
      across = std::max(across, gap.across);
      it = left.erase(it);
    }
    out.push_back(gaps_of_one_part(name(part), others, narrowest, widest, across, tail));
  }
  for (const auto& pair : left)
    out.push_back(one_gap(name(pair.first), name(pair.second), unresolved.at(pair), tail));
  return out;
}

} // namespace magfem
