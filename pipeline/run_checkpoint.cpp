#include "pipeline/run_checkpoint.hpp"

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "core/input_error.hpp"
#include "pipeline/build_info.hpp"

namespace magfem {

namespace {

// FNV-1a: stable across builds and platforms (std::hash is not promised to be).
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (const unsigned char c : text)
    h = (h ^ c) * 1099511628211ull;
  return h;
}

} // namespace

std::string checkpoint_identity(const std::string& command, const std::string& case_file,
                                const std::string& options) {
  std::stringstream text;
  text << std::ifstream(case_file, std::ios::binary).rdbuf();
  return checkpoint_identity_of_text(command, text.str(), options);
}

std::string checkpoint_identity_of_text(const std::string& command, const std::string& case_text,
                                        const std::string& options) {
  char hash[32];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(fnv1a(case_text)));
  return command + " " + options + " case " + hash + " commit " + magfem_git_commit();
}

RunCheckpoint::RunCheckpoint(const std::filesystem::path& out_dir, const std::string& identity,
                             bool resume)
    : path_(out_dir / file_name), identity_(identity) {
  if (resume) {
    std::ifstream in(path_);
    std::string line;
    if (!in || !std::getline(in, line)) {
      // Worded for the command line's --resume and Python's resume=True alike.
      std::cerr << "magfem: note: resume: no checkpoint in " << out_dir.string()
                << ", starting from the beginning\n";
    } else {
      const auto head = nlohmann::json::parse(line, nullptr, false);
      if (head.is_discarded() || head.value("identity", "") != identity)
        throw InputError(
            "<command line>", 0, "--resume",
            "the checkpoint in " + out_dir.string() +
                " was left by a different run (case file, options or magfem "
                "build differ): " +
                (head.is_discarded() ? std::string("unreadable") : head.value("identity", "")) +
                "; start again without resuming");
      while (std::getline(in, line)) {
        const auto entry = nlohmann::json::parse(line, nullptr, false);
        if (entry.is_discarded() || !entry.contains("key") || !entry.contains("value"))
          continue; // cut short by the interrupt: computed again
        done_[entry["key"].get<std::string>()] = entry["value"];
      }
      restored_ = done_.size();
    }
  }
}

void RunCheckpoint::open() {
  std::error_code ec;
  std::filesystem::create_directories(path_.parent_path(), ec);
  // Rewritten from what was read: a torn last line does not stay in the middle of the file.
  out_.open(path_, std::ios::trunc);
  out_ << nlohmann::json{{"identity", identity_}}.dump() << "\n";
  for (const auto& [key, value] : done_)
    out_ << nlohmann::json{{"key", key}, {"value", value}}.dump() << "\n";
  out_.flush();
  if (!out_) { // the run goes on; only --resume loses what it would have found
    std::cerr << "magfem: note: cannot write the checkpoint " << path_.string() << "\n";
    unwritable_ = true;
  }
}

std::optional<nlohmann::json> RunCheckpoint::find(const std::string& key) const {
  const auto it = done_.find(key);
  if (it == done_.end())
    return std::nullopt;
  return it->second;
}

void RunCheckpoint::record(const std::string& key, const nlohmann::json& value) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!out_.is_open() && !unwritable_)
    open();
  if (unwritable_)
    return;
  out_ << nlohmann::json{{"key", key}, {"value", value}}.dump() << "\n";
  out_.flush();
}

void RunCheckpoint::remove() {
  out_.close();
  std::error_code ignored; // none may have been written
  std::filesystem::remove(path_, ignored);
}

std::string RunCheckpoint::key_of(double position) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", position);
  return buf;
}

std::string RunCheckpoint::mesh_scale_key(double mesh_scale) {
  return key_of(mesh_scale > 0 ? mesh_scale : 1.0);
}

} // namespace magfem
