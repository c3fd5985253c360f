#pragma once
// Text as report.html shows it. The catalogue and the evaluators write for the markdown
// report and for developers (backticks, "paper_targets D", paths of the machine that ran the
// check); a reader of the HTML page needs the same facts without those: code in <code>, the
// figure the tolerance belongs to, paths relative to the project.
#include <string>

namespace magfem {

// &, <, >, " escaped.
std::string html_escape(const std::string& s);

// Escaped, with `code` spans as <code> and **bold** as <b> (the markdown the catalogue and the
// evaluators' notes use); an unpaired backtick is dropped rather than shown.
std::string html_text(const std::string& s);

// Rewrites absolute paths in `text` relative to the project: `root` (an absolute folder, the
// checkout or the installed share folder) is removed where it prefixes a path; any other
// absolute path keeps only its part from a project folder (examples/, validation/, ...) or,
// failing that, its file name, so that no path of the machine that ran the check remains.
std::string project_relative(const std::string& text, const std::string& root);

// The catalogue's tolerance reasons cite the project's target list by letter ("paper_targets
// D (3 points)"); the page names the figure instead: "target for Table 6.3 (3 points)".
std::string readable_reason(const std::string& reason, const std::string& section);

// A table label for a long quantity description: its first clause (up to the first comma or
// parenthesis), at most about `max_chars` characters cut at a word.
std::string short_quantity(const std::string& quantity, std::size_t max_chars = 56);

} // namespace magfem
