#pragma once
// Outputs of `magfem validate`: results.csv (the contract columns), results.json (the same
// plus settings, versions, details), report.md (the summary table) and report.html (one
// self-contained page: summary, citations, table, a section per entry with inline SVG plots).
#include <string>

#include "core/output_stage.hpp"
#include "validation/validate.hpp"

namespace magfem {

// The columns of results.csv, in order.
extern const char* const validation_csv_header;

std::string validation_csv(const ValidationRun& run);
std::string validation_json(const ValidationRun& run);
std::string validation_markdown(const ValidationRun& run);
// The page (report_html.cpp): summary, citations, compact table, a section per entry with
// its gnuplot plots (report_plot.hpp); paths relative to the project.
std::string validation_html(const ValidationRun& run);

// Writes the four files into the stage (the caller commits).
void write_validation_outputs(const ValidationRun& run, OutputStage& stage);

} // namespace magfem
