#include "python/call_checkpoint.hpp"

#include "core/input_error.hpp"

namespace magfem::python {

void bind_checkpoint_request(pybind11::module_& m) {
  pybind11::class_<CheckpointRequest>(m, "CheckpointRequest",
                                      "The checkpoint_dir and resume arguments of a study call.")
      .def(pybind11::init<>())
      .def_readwrite("dir", &CheckpointRequest::dir)
      .def_readwrite("resume", &CheckpointRequest::resume);
}

std::string case_call_identity(const std::string& command, const std::string& options,
                               const std::string& path, const std::string& text,
                               const std::map<std::string, double>& parameters) {
  std::string full = options;
  for (const auto& [name, value] : parameters) // appended: GCC 12 -Wrestrict misfires on +
    full.append(" case-param ").append(name).append("=").append(RunCheckpoint::key_of(value));
  return path.empty() ? checkpoint_identity_of_text(command, text, full)
                      : checkpoint_identity(command, path, full);
}

std::unique_ptr<RunCheckpoint> open_call_checkpoint(const CheckpointRequest& request,
                                                    const std::string& where,
                                                    const std::string& identity) {
  if (request.dir.empty()) {
    if (request.resume)
      throw InputError(where, 0, "checkpoint_dir",
                       "resume=True needs the directory of the checkpoint to continue");
    return nullptr;
  }
  try {
    return std::make_unique<RunCheckpoint>(request.dir, identity, request.resume);
  } catch (const InputError& e) { // the command line's reason, the argument's name
    if (e.file() != "<command line>")
      throw;
    throw InputError(where, 0, "resume", e.reason());
  }
}

} // namespace magfem::python
