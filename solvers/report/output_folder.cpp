#include "report/output_folder.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "common/errors.hpp"
#include "common/user_text.hpp"

namespace bb {
namespace {

namespace fs = std::filesystem;

std::string shown(const fs::path& path) { return printable(path.string()); }

// The permissions a folder or file made by mkdir/open would get (mkdtemp and mkstemp use 0700/0600).
fs::perms default_perms(bool folder) {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<fs::perms>((folder ? 0777 : 0666) & ~mask);
}

// A new folder `parent/<prefix>XXXXXX`.
fs::path make_temp_folder(const fs::path& parent, const std::string& prefix, const fs::path& for_whom) {
  std::string name = (parent / fmt::format("{}XXXXXX", prefix)).string();
  if (!::mkdtemp(name.data()))
    throw OutputError(
        fmt::format("report folder {}: cannot write in {} ({})", shown(for_whom), shown(parent), std::strerror(errno)));
  std::error_code ignored;
  fs::permissions(name, default_perms(true), ignored);
  return name;
}

// Creates `folder` (and its parents) unless it exists; throws OutputError naming `what`.
void ensure_folder(const fs::path& folder, const std::string& what) {
  std::error_code ec;
  for (fs::path p = folder; !p.empty() && p != p.parent_path(); p = p.parent_path())  // "file/sub": name the file
    if (fs::exists(p, ec) && !fs::is_directory(p, ec))
      throw OutputError(fmt::format("{}: {} exists and is not a folder", what, shown(p)));
  fs::create_directories(folder, ec);
  if (ec) throw OutputError(fmt::format("{}: cannot create the folder {} ({})", what, shown(folder), ec.message()));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw OutputError(fmt::format("{}: cannot write in the folder {} ({})", what, shown(folder), std::strerror(errno)));
}

}  // namespace

StagedFolder::StagedFolder(fs::path destination, const std::vector<fs::path>& inputs)
    : destination_(std::move(destination)) {
  if (!destination_.has_filename()) destination_ = destination_.parent_path();  // "reports/x/"
  const std::string name = destination_.filename().string();
  const std::string what = "report folder " + shown(destination_);
  if (name.empty() || name == "." || name == "..")
    throw OutputError(
        fmt::format("{}: names no folder of its own (the report replaces its folder); give one, e.g. "
                    "reports/<case-name>",
                    what));
  std::error_code ec;
  const fs::file_status status = fs::status(destination_, ec);
  if (fs::exists(status) && !fs::is_directory(status))
    throw OutputError(fmt::format("{}: exists and is not a folder", what));
  if (fs::is_directory(status) && !fs::is_empty(destination_, ec) && !fs::exists(destination_ / "summary.json") &&
      !fs::exists(destination_ / "report.md"))
    throw OutputError(
        fmt::format("{}: an existing folder that holds no bladebench report (no summary.json or "
                    "report.md); the report would replace it: give a new or empty folder",
                    what));
  require_outside(destination_, inputs, what);
  fs::path parent = destination_.parent_path();
  if (parent.empty()) parent = ".";
  ensure_folder(parent, what);
  temp_ = make_temp_folder(parent, fmt::format(".{}.tmp-", name), destination_);
}

StagedFolder::~StagedFolder() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(temp_, ignored);
}

void StagedFolder::commit() {
  const std::string what = "report folder " + shown(destination_);
  std::error_code ec;
  fs::path old;  // the earlier report, moved aside until the new one is in place
  if (fs::symlink_status(destination_, ec).type() != fs::file_type::not_found) {
    old =
        make_temp_folder(temp_.parent_path(), fmt::format(".{}.old-", destination_.filename().string()), destination_);
    fs::remove(old, ec);  // a free name: rename() cannot put a symbolic link or a file onto a folder
    if (std::rename(destination_.c_str(), old.c_str()) != 0)
      throw OutputError(fmt::format("{}: cannot replace the earlier report ({})", what, std::strerror(errno)));
  }
  if (std::rename(temp_.c_str(), destination_.c_str()) != 0) {
    const int error = errno;
    if (!old.empty()) std::rename(old.c_str(), destination_.c_str());
    throw OutputError(fmt::format("{}: cannot move the report into place ({})", what, std::strerror(error)));
  }
  committed_ = true;
  if (!old.empty()) fs::remove_all(old, ec);
}

void prepare_output_parent(const fs::path& folder, const std::string& option) {
  ensure_folder(folder, option + " " + shown(folder));
}

bool lies_within(const fs::path& path, const fs::path& folder) {
  // Both resolved as far as they exist, so that "a/../b" or a link into the folder is seen.
  const auto resolved = [](const fs::path& p) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(p, ec), ec);
    return ec ? fs::absolute(p, ec).lexically_normal() : r;
  };
  const fs::path p = resolved(path);
  fs::path f = resolved(folder);
  if (!f.has_filename()) f = f.parent_path();  // "folder/"
  return std::mismatch(f.begin(), f.end(), p.begin(), p.end()).first == f.end();
}

void require_outside(const fs::path& out, const std::vector<fs::path>& inputs, const std::string& what) {
  for (const fs::path& input : inputs)
    if (!input.empty() && lies_within(input, out))
      throw OutputError(fmt::format("{}: would replace {}, an input of this command; write elsewhere", what,
                                    shown(input)));
}

void require_replaceable_file(const fs::path& file) {
  std::error_code ignored;
  // rename() would put a regular file in place of a device, a FIFO, a link or a folder's entry.
  if (const fs::file_status st = fs::symlink_status(file, ignored); fs::exists(st) && !fs::is_regular_file(st))
    throw OutputError(fmt::format("{}: exists and is not a regular file (a folder, a link, a device or a FIFO); "
                                  "it is not replaced",
                                  shown(file)));
}

void replace_file(const fs::path& file, const std::function<void(const fs::path&)>& write) {
  require_replaceable_file(file);
  std::error_code ignored;
  fs::path parent = file.parent_path();
  if (parent.empty()) parent = ".";
  std::string temp = (parent / fmt::format(".{}.tmp-XXXXXX", file.filename().string())).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw OutputError(fmt::format("{}: cannot write ({})", shown(file), std::strerror(errno)));
  ::close(fd);
  fs::permissions(temp, default_perms(false), ignored);
  try {
    write(temp);
  } catch (...) {
    fs::remove(temp, ignored);
    throw;
  }
  if (std::rename(temp.c_str(), file.c_str()) != 0) {
    const int error = errno;
    fs::remove(temp, ignored);
    throw OutputError(fmt::format("{}: cannot write ({})", shown(file), std::strerror(error)));
  }
}

void write_file_atomically(const fs::path& file, const std::string& text) {
  replace_file(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw OutputError(fmt::format("{}: write failed", shown(file)));
  });
}

}  // namespace bb
