#include "core/output_stage.hpp"

#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace magfem {

OutputStage::OutputStage(std::filesystem::path out_dir) : out_dir_(std::move(out_dir)) {
  staging_ = out_dir_ / (".magfem-staging-" + std::to_string(::getpid()));
  created_out_dir_ = !std::filesystem::exists(out_dir_);
}

OutputStage::~OutputStage() {
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
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void OutputStage::commit() {
  for (const auto& name : names_) {
    std::filesystem::rename(staging_ / name, out_dir_ / name);
  }
  committed_ = true;
}

} // namespace magfem
