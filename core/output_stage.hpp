#pragma once
// All-or-nothing outputs. Files are written into a hidden staging folder inside the output
// directory and renamed into place by commit(); if commit() is never reached (an error, a
// solver that did not converge) the destructor removes the staging folder, so a failed run
// leaves nothing that could be mistaken for a result.
//
// Reruns into the same directory: a manifest (.magfem-outputs) lists what the last run
// wrote, and commit() deletes those of its files that this run does not write (a probe
// removed from the case), never anything else. The record file (summary.json unless told
// otherwise) is deleted first and renamed into place last, so a commit interrupted half way
// (power cut, SIGKILL) leaves a directory without a record: recognisably incomplete, never a
// mix of two runs that looks whole. During the renames the manifest lists the files of both
// runs, so the next run into the directory removes whatever the cut one left.
#include <filesystem>
#include <string>
#include <vector>

namespace magfem {

class OutputStage {
public:
  explicit OutputStage(std::filesystem::path out_dir, std::string record = "summary.json");
  ~OutputStage();
  OutputStage(const OutputStage&) = delete;
  OutputStage& operator=(const OutputStage&) = delete;

  // Path to write `name` to (inside the staging folder). Remembers the name for commit().
  std::filesystem::path path_for(const std::string& name);
  // Writes a text file in one go.
  void write_text(const std::string& name, const std::string& text);
  // Moves every staged file into the output directory (replacing older ones), the record
  // last, and removes the files of the previous run that this one did not write.
  void commit();

  static constexpr const char* manifest_name = ".magfem-outputs";

  const std::filesystem::path& out_dir() const { return out_dir_; }
  // The files this run wrote, the record first, then in the order they were staged: what
  // the console's "wrote" line lists (never a hand-kept list that forgets one).
  std::vector<std::string> written() const;

private:
  std::filesystem::path out_dir_;
  std::string record_;
  std::filesystem::path staging_;
  std::vector<std::string> names_;
  bool committed_ = false;
  bool created_out_dir_ = false;
};

} // namespace magfem
