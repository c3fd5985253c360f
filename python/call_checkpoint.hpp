#pragma once
// The checkpoint of a Python call (magfem.sweep, study, validate with checkpoint_dir=DIR and
// resume=): the command line's (pipeline/run_checkpoint.hpp), DIR/.magfem-checkpoint.jsonl,
// kept as items finish and restored with resume=True, so that a call stopped by Ctrl-C, an
// exception of its progress callable, kill or a crash continues where it stopped. As the
// command line removes it once its outputs are written, the call removes it once its result
// is complete; interrupted, the call leaves it for resume.
//
// The identity names the case by its text's hash (a file's contents, or Case.from_dict's
// YAML) and adds the case's parameter overrides, so that a resume of another case, other
// overrides or other options is refused with the command line's message.
#include <map>
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "pipeline/run_checkpoint.hpp"

namespace magfem::python {

struct CheckpointRequest {
  std::string dir; // empty: no checkpoint
  bool resume = false;
};

// The checkpoint of a call (null without a directory) for a run named `identity`. A refused
// resume is an InputError at `where` naming the argument resume (the command line's reason);
// resume without a directory is one naming checkpoint_dir.
std::unique_ptr<RunCheckpoint> open_call_checkpoint(const CheckpointRequest& request,
                                                    const std::string& where,
                                                    const std::string& identity);

// The identity of a run of `command` with `options` (their text, exact values) on the case
// named by path (a file) or text (Case.from_dict), with its parameter overrides.
std::string case_call_identity(const std::string& command, const std::string& options,
                               const std::string& path, const std::string& text,
                               const std::map<std::string, double>& parameters);

// magfem._core.CheckpointRequest (the checkpoint_dir and resume arguments).
void bind_checkpoint_request(pybind11::module_& m);

} // namespace magfem::python
