#pragma once
// The closest of a list of names to a misspelt one, for error messages ("unknown field
// 'magnetisation' ... did you mean 'magnetization'?", material 'M19' for 'M-19').
#include <string>
#include <vector>

namespace magfem {

// The candidate nearest to `word` when it is near enough to be a slip, else "". Names are
// compared without case, '-', '_' and spaces (so 'M19' meets 'M-19' at distance 0), by the
// optimal-string-alignment distance (insertions, deletions, substitutions, swaps of
// neighbours), allowing 1 edit for names up to 4 characters, 2 up to 8, 3 beyond. Ties go to
// the first candidate.
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);

// " (did you mean 'X'?)" for closest_name's answer, or "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

} // namespace magfem
