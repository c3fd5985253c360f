#include "core/output_stage.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "core/interrupt.hpp"

namespace magfem {

OutputStage::OutputStage(std::filesystem::path out_dir, std::string record)
    : out_dir_(std::move(out_dir)), record_(std::move(record)) {
  staging_ = out_dir_ / (".magfem-staging-" + std::to_string(::getpid()));
  created_out_dir_ = !std::filesystem::exists(out_dir_);
  register_staging(staging_, created_out_dir_ ? out_dir_ : std::filesystem::path());
}

OutputStage::~OutputStage() {
  unregister_staging(staging_);
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);
  // An output directory we created and never filled goes too.
  if (!committed_ && created_out_dir_ && std::filesystem::is_empty(out_dir_, ec))
    std::filesystem::remove(out_dir_, ec);
}

std::filesystem::path OutputStage::path_for(const std::string& name) {
  std::filesystem::create_directories(staging_);
  names_.push_back(name);
  return staging_ / name;
}

void OutputStage::write_text(const std::string& name, const std::string& text) {
  const auto path = path_for(name);
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out)
    throw std::runtime_error("cannot write " + path.string());
}

namespace {

std::vector<std::string> read_manifest(const std::filesystem::path& path) {
  std::vector<std::string> names;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    // Only plain names: a manifest edited to point elsewhere cannot make us delete it.
    if (!line.empty() && line.find('/') == std::string::npos && line != "." && line != "..")
      names.push_back(line);
  return names;
}

} // namespace

std::vector<std::string> OutputStage::written() const {
  std::vector<std::string> out;
  if (std::find(names_.begin(), names_.end(), record_) != names_.end())
    out.push_back(record_);
  for (const auto& name : names_)
    if (name != record_ && name.rfind(manifest_name, 0) != 0)
      out.push_back(name);
  return out;
}

void OutputStage::commit() {
  namespace fs = std::filesystem;
  const bool has_record = std::find(names_.begin(), names_.end(), record_) != names_.end();
  // The manifest in place during the transition lists the files of both runs, so that a
  // commit cut short (power cut, SIGKILL) leaves no file that a later run would not clean up.
  const std::vector<std::string> previous = read_manifest(out_dir_ / manifest_name);
  std::string both, manifest;
  for (const auto& name : names_)
    manifest += name + "\n";
  both = manifest;
  for (const auto& old : previous)
    if (std::find(names_.begin(), names_.end(), old) == names_.end())
      both += old + "\n";
  // Staged before anything moves, so a full disk fails here, with the old run intact.
  const std::string transition = std::string(manifest_name) + ".transition";
  write_text(manifest_name, manifest);
  write_text(transition, both);
  names_.resize(names_.size() - 2);

  // From here on the directory is in transition: no record until the end. An interrupt
  // waits for the end (core/interrupt.hpp).
  const auto hold = hold_outputs();
  fs::rename(staging_ / transition, out_dir_ / manifest_name);
  if (has_record)
    fs::remove(out_dir_ / record_);
  for (const auto& old : previous)
    if (std::find(names_.begin(), names_.end(), old) == names_.end())
      fs::remove(out_dir_ / old);
  for (const auto& name : names_)
    if (name != record_)
      fs::rename(staging_ / name, out_dir_ / name);
  fs::rename(staging_ / manifest_name, out_dir_ / manifest_name);
  if (has_record)
    fs::rename(staging_ / record_, out_dir_ / record_);
  committed_ = true;
}

} // namespace magfem
