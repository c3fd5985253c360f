#include "python/validate.hpp"

#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "core/input_error.hpp"
#include "python/background_call.hpp"
#include "python/call_checkpoint.hpp"
#include "validation/validate.hpp"
#include "validation/validate_report.hpp"

namespace py = pybind11;

namespace magfem::python {
namespace {

std::string validate_entries(const std::string& tier, const std::vector<std::string>& entries,
                             const std::string& source, int jobs, const std::string& catalogue,
                             const CheckpointRequest& checkpoint_request, py::object progress) {
  ValidateOptions o;
  if (tier != "quick" && tier != "full")
    throw InputError("<validate>", 0, "tier", "must be 'quick' or 'full', not '" + tier + "'");
  o.tier = tier == "full" ? ValidationTier::full : ValidationTier::quick;
  if (!entries.empty() && !source.empty())
    throw InputError("<validate>", 0, "entries", "give entries or source, not both");
  if (jobs < 0)
    throw InputError("<validate>", 0, "jobs", "must be a positive integer");
  o.only = entries;
  o.source = source;
  o.jobs = jobs;
  o.catalogue = catalogue;
  ValidationRun run = select_validation(o);
  // The command line's checkpoint, identity and all: a Python call and `magfem validate
  // --out DIR --resume` continue each other's runs.
  const auto checkpoint =
      open_call_checkpoint(checkpoint_request, "<validate>", validation_checkpoint_identity(run));
  BackgroundCall call(std::move(progress), "entry");
  const auto total = static_cast<int>(run.results.size());
  call.run([&] {
    evaluate_validation(
        run, checkpoint.get(),
        [&](const EntryResult&, int done, double, bool) { call.report(done, total); },
        call.stop_token());
  });
  if (checkpoint)
    checkpoint->remove(); // the result is complete
  return validation_json(run);
}

} // namespace

void bind_validate(py::module_& m) {
  m.def("validate", &validate_entries, py::arg("tier"), py::arg("entries"), py::arg("source"),
        py::arg("jobs"), py::arg("catalogue"), py::arg("checkpoint"), py::arg("progress"),
        "Runs `magfem validate` in-process; returns results.json's text.");
}

} // namespace magfem::python
