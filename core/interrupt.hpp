#pragma once
// Ctrl-C (SIGINT) and kill (SIGTERM) during a run: no partial outputs, a message, and the
// shell's exit code for the signal (130 / 143).
//
// Why a thread: cleaning up means deleting folders, which a signal handler may not do (no
// allocation, no locks). The handler only wakes a dedicated thread, which removes the staging
// folder of every OutputStage that has not committed (a commit in progress is waited for: it
// finishes, and its outputs are whole), prints the message and exits the process.
#include <filesystem>
#include <mutex>

namespace magfem {

// Call first thing in main(). Idempotent.
void install_interrupt_handler();

// Bookkeeping for OutputStage: what to remove if the run is interrupted now.
// `remove_dir_if_empty` is the output directory when the stage created it (else empty).
void register_staging(const std::filesystem::path& staging,
                      const std::filesystem::path& remove_dir_if_empty);
void unregister_staging(const std::filesystem::path& staging);
// Held by OutputStage::commit(): an interrupt waits until the renames are done.
std::unique_lock<std::mutex> hold_outputs();

} // namespace magfem
