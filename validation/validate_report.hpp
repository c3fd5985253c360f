#pragma once
// Outputs of `magfem validate`: results.csv (the contract columns), results.json (the same
// plus settings, versions, details), report.md (the summary table) and report.html (one
// self-contained page: table, a paragraph per figure, inline SVG plots).
#include <string>

#include "validation/validate.hpp"
#include "core/output_stage.hpp"

namespace magfem {

// The columns of results.csv, in order.
extern const char* const validation_csv_header;

std::string validation_csv(const ValidationRun& run);
std::string validation_json(const ValidationRun& run);
std::string validation_markdown(const ValidationRun& run);
std::string validation_html(const ValidationRun& run);
// An inline SVG line plot (no external resources).
std::string plot_svg(const Plot& plot);

// Writes the four files into the stage (the caller commits).
void write_validation_outputs(const ValidationRun& run, OutputStage& stage);

} // namespace magfem
