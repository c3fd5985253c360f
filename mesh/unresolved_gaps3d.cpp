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

// A length in mm or a factor, to 3 significant digits.
std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// What the warning says after its gaps and their elements, for one gap or several.
std::string consequence(int order, int layers, double scale, bool several) {
  const std::string gap = several ? "the gaps" : "the gap";
  return "their nodes (order " + std::to_string(order) + ") farther apart than " + gap +
         (several ? " are" : " is") + " wide (gap_layers " + std::to_string(layers) +
         ", sizes scaled by " + number(scale) +
         " in all: the case's mesh scale times --mesh-scale): the field in " +
         (several ? "these gaps" : "the gap") + " is not resolved; scale the sizes by at most " +
         std::to_string(order * layers) + " in all, or make the mesh size near " + gap + " smaller";
}

std::string one_gap(const std::string& a, const std::string& b, const UnresolvedGap& gap) {
  return "the " + number(gap.width * 1e3) + " mm air gap between parts " + quoted(a) + " and " +
         quoted(b) + " has elements of about " + number(gap.across * 1e3) + " mm across it, ";
}

std::string gaps_of_one_part(const std::string& part, const std::vector<std::string>& others,
                             double narrowest, double widest, double across) {
  const std::string widths = narrowest == widest
                                 ? number(narrowest * 1e3)
                                 : number(narrowest * 1e3) + " to " + number(widest * 1e3);
  return "the air gaps between part " + quoted(part) + " and " + std::to_string(others.size()) +
         " other parts (" + some_names(others) + "), " + widths +
         " mm wide, have elements of up to about " + number(across * 1e3) + " mm across them, ";
}

} // namespace

std::vector<std::string> unresolved_gap_warnings(const std::vector<std::string>& part_names,
                                                 int order, int gap_layers, double scale,
                                                 const UnresolvedGaps& unresolved) {
  order = std::max(1, order);
  gap_layers = std::max(1, gap_layers);
  std::set<std::pair<int, int>> left;
  for (const auto& [pair, gap] : unresolved)
    if (gap.across > order * gap.width)
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
    out.push_back(gaps_of_one_part(name(part), others, narrowest, widest, across) +
                  consequence(order, gap_layers, scale, true));
  }
  for (const auto& pair : left)
    out.push_back(one_gap(name(pair.first), name(pair.second), unresolved.at(pair)) +
                  consequence(order, gap_layers, scale, false));
  return out;
}

} // namespace magfem
