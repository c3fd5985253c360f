#pragma once
// study.png: each objective against the first parameter, one line per combination of the
// other parameters (gnuplot, as sweep.png; none if gnuplot is missing).
#include <filesystem>
#include <string>
#include <vector>

#include "app/study.hpp"

namespace magfem {

// Returns false with the reason in `why` if no plot was made.
bool plot_study(const StudyOptions& options, const std::vector<StudyDesign>& designs,
                const std::filesystem::path& png, std::string& why);

} // namespace magfem
