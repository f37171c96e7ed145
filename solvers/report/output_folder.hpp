// Report folders that appear complete or not at all, so that an interrupted or failed run never
// leaves a half-written report that reads as a result.
#pragma once
#include <filesystem>
#include <string>

namespace bb {

// A report folder written under a temporary name and moved into place once complete. Files go to
// a hidden sibling of the destination, `.<name>.tmp-XXXXXX` (same parent, so the final rename is
// atomic), and commit() makes it the destination, replacing an earlier report there. A folder that
// is never committed (an exception, a failed write) is removed by the destructor; a process killed
// outright leaves its hidden sibling, never a partial <name>.
class StagedFolder {
 public:
  // Throws OutputError naming `destination` when it cannot be used: its name is empty, "." or "..";
  // it exists and is not a folder; it is a folder that is neither empty nor a bladebench report
  // (summary.json or report.md), which commit() would replace; its parent cannot be created or
  // written in.
  explicit StagedFolder(std::filesystem::path destination);
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where the files go until commit().
  const std::filesystem::path& path() const { return temp_; }
  const std::filesystem::path& destination() const { return destination_; }
  // Replaces the destination with the written folder. Throws OutputError when it cannot.
  void commit();

 private:
  std::filesystem::path destination_, temp_;
  bool committed_ = false;
};

// A folder that receives report folders (validate --out, run --out with several cases): created
// when missing. Throws OutputError starting with `option` and the path when it is not a folder or
// cannot be created or written in.
void prepare_output_parent(const std::filesystem::path& folder, const std::string& option);

// Writes `text` to `file` through a temporary sibling renamed over it: a reader sees the old file
// or the new one, never part of it.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace bb
