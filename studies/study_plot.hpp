#pragma once
// study.png (gnuplot, as sweep.png; none if gnuplot is missing): with two parameters that
// each take several values, a filled contour map of each objective over the two (a designer
// reads the ridge of a 2D study off a map, not off a bundle of lines); otherwise each objective
// against the first parameter, one line per combination of the other parameters.
#include <filesystem>
#include <string>
#include <vector>

#include "studies/study.hpp"

namespace magfem {

// Returns false with the reason in `why` if no plot was made.
bool plot_study(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                const std::filesystem::path& png, std::string& why);

} // namespace magfem
