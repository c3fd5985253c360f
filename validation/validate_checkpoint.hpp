#pragma once
// A finished catalogue entry as a checkpoint record (pipeline/run_checkpoint.hpp), so that an
// interrupted `magfem validate` continues with --resume where it stopped and writes the same
// results as an uninterrupted run (numbers round-trip exactly; the details keep their order).
#include <nlohmann/json.hpp>

#include "validation/validate.hpp"

namespace magfem {

nlohmann::json entry_to_checkpoint(const EntryResult& r);
// Restores everything but r.entry (which the caller has set). Throws nlohmann's exceptions
// on a record of another shape (the caller then evaluates the entry again).
void entry_from_checkpoint(const nlohmann::json& j, EntryResult& r);

} // namespace magfem
