// Report folders that appear complete or not at all, so that an interrupted or failed run never
// leaves a half-written report that reads as a result.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

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
  // (summary.json or report.md), which commit() would replace; it holds one of `inputs` (the files
  // the command reads); its parent cannot be created or written in.
  explicit StagedFolder(std::filesystem::path destination, const std::vector<std::filesystem::path>& inputs = {});
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

// Writes `file` through `write`, which fills a temporary sibling that is then renamed over `file`: a
// reader sees the old file or the new one, never part of it. Throws OutputError naming `file` when
// it exists and is not a regular file (a device, a FIFO, a link or a folder is never replaced).
void replace_file(const std::filesystem::path& file, const std::function<void(const std::filesystem::path&)>& write);
// The check of replace_file alone, for a command that writes only after a long run.
void require_replaceable_file(const std::filesystem::path& file);
// replace_file with `text` as the contents.
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

// Whether `path` is `folder` or lies under it, both resolved as far as they exist.
bool lies_within(const std::filesystem::path& path, const std::filesystem::path& folder);
// Throws OutputError starting with `what` when a write to `out` (a file, or a folder replaced whole)
// would replace one of `inputs`.
void require_outside(const std::filesystem::path& out, const std::vector<std::filesystem::path>& inputs,
                     const std::string& what);

}  // namespace bb
