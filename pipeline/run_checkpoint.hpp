#pragma once
// The finished positions of a sweep (entries of validate, designs of study), kept on disk as
// each one finishes, so that a run stopped by Ctrl-C, kill or a crash can be continued with
// --resume instead of started again.
//
// The file is <out>/.magfem-checkpoint.jsonl: a first line naming the run (the command, the
// options that change results, a hash of the case file and the magfem commit), then one JSON
// object per finished position, appended and flushed as it finishes. Doubles are written with
// 17 significant digits, so a restored position is bit for bit the computed one and a resumed
// run writes the same CSV as an uninterrupted run. A line cut short by the interrupt is
// ignored (that position is computed again). The file is not an output: the all-or-nothing
// outputs are written by OutputStage at the end, after which the checkpoint is removed.
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace magfem {

class RunCheckpoint {
public:
  static constexpr const char* file_name = ".magfem-checkpoint.jsonl";

  // The checkpoint of a run named `identity` in out_dir. With `resume`, the positions an
  // earlier run with the same identity finished are loaded; a checkpoint of a different run
  // is an InputError (field --resume). Without it, any old checkpoint is replaced. Nothing
  // is written (not even out_dir) before the first record(): bad input leaves no trace.
  RunCheckpoint(const std::filesystem::path& out_dir, const std::string& identity, bool resume);

  // The recorded result of position `key`, if an earlier run finished it.
  std::optional<nlohmann::json> find(const std::string& key) const;
  // Records a finished position (thread safe; on disk when this returns).
  void record(const std::string& key, const nlohmann::json& value);
  std::size_t n_restored() const { return restored_; }
  // After the outputs are committed: the checkpoint has served its purpose.
  void remove();

  // A key for a position value that is exact (17 significant digits).
  static std::string key_of(double position);
  // The FE mesh scale in an identity: 0 ("as in the case", the command line's default) as 1
  // (Python's), the same mesh (run2d/run3d multiply the case's sizes by it, 0 taken as 1), so
  // that a run started by either can be resumed by the other.
  static std::string mesh_scale_key(double mesh_scale);

private:
  void open(); // on the first record(): the header and the restored positions
  std::filesystem::path path_;
  std::string identity_;
  std::map<std::string, nlohmann::json> done_;
  std::size_t restored_ = 0;
  std::ofstream out_;
  bool unwritable_ = false;
  std::mutex mutex_;
};

// Identity text of a run: the words given, plus the case file's contents hash and the commit.
std::string checkpoint_identity(const std::string& command, const std::string& case_file,
                                const std::string& options);
// The same for a case given as its text (Python's Case.from_dict has no file): a file with
// that text gives the same identity.
std::string checkpoint_identity_of_text(const std::string& command, const std::string& case_text,
                                        const std::string& options);

} // namespace magfem
