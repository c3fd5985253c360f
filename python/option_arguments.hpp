#pragma once
// A Python call that goes through a command's own option parser (magfem.optimize,
// magfem.coil_pitch), so that it checks and reads its arguments exactly as the command line
// does: numbers written for the parser, and the parser's errors renamed for Python.
#include <map>
#include <optional>
#include <string>

#include "casefile/adapt_spec.hpp"
#include "core/input_error.hpp"

namespace magfem::python {

// A number as an option value that reads back as the same double (17 significant digits).
std::string option_number(double v);

// An InputError of the option parser ("<command line>", field "--option") with `where`
// ("<optimize>") and the argument's Python name from `names` (option -> argument) in its
// place; the reason stays the command line's. Errors of the case file pass unchanged.
InputError as_argument_error(const InputError& e, const std::string& where,
                             const std::map<std::string, std::string>& names);

// The adaptive solve's arguments (accuracy in percent, max_passes, max_unknowns; None: the
// case's) checked by the command line's parse_cli_adapt, with its messages, as InputErrors at
// `where` ("<solve>", "<study>") naming the argument.
AdaptOverrides adapt_arguments(const std::string& where, std::optional<double> accuracy_pct,
                               std::optional<int> max_passes, std::optional<double> max_unknowns);
// Those options' Python names, for as_argument_error (--accuracy -> accuracy, ...).
const std::map<std::string, std::string>& adapt_argument_names();

} // namespace magfem::python
