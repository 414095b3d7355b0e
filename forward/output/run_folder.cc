#include "output/run_folder.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace vs {

namespace fs = std::filesystem;

namespace {

// A sibling of `dest` named ".<name>.<tag>-<pid>" (same file system: the swap is a rename).
fs::path sibling(const fs::path& dest, const std::string& tag) {
  const fs::path parent = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  std::string name = ".";
  name.append(dest.filename().string()).append(".").append(tag).append("-");
  name.append(std::to_string(::getpid()));
  return parent / name;
}

}  // namespace

RunFolder::RunFolder(const std::string& destination, const std::string& owner_file) {
  fs::path dest = fs::path(destination).lexically_normal();
  if (dest.filename().empty()) dest = dest.parent_path();  // "out/" -> "out"
  if (dest.empty() || dest == "." || dest == "..") {
    throw InputError("output folder '" + destination +
                     "': give a folder of its own (e.g. out/run1): the run replaces it whole");
  }
  destination_ = dest.string();
  std::error_code ec;
  if (fs::exists(dest, ec)) {
    if (!fs::is_directory(dest, ec)) {
      throw InputError("output folder " + destination_ + " exists and is not a folder");
    }
    const bool empty = fs::is_empty(dest, ec);
    if (!empty && !fs::exists(dest / owner_file, ec)) {
      throw InputError("output folder " + destination_ + " is not empty and holds no " +
                       owner_file +
                       " of an earlier run: a run replaces its folder whole, so give a new or "
                       "empty folder (or remove this one)");
    }
  }
  const fs::path parent = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  const fs::path staging = sibling(dest, "staging");
  fs::remove_all(staging, ec);
  if (!fs::create_directories(staging, ec) || ec) {
    throw InputError("cannot create the staging folder " + staging.string() + ": " + ec.message());
  }
  staging_ = staging.string();
}

RunFolder::~RunFolder() {
  if (committed_) return;
  std::error_code ec;
  if (fs::is_empty(staging_, ec)) fs::remove(staging_, ec);
}

void RunFolder::commit() {
  const fs::path dest(destination_), staging(staging_);
  const fs::path previous = sibling(dest, "previous");
  std::error_code ec;
  fs::remove_all(previous, ec);
  const bool had_previous = fs::exists(dest, ec);
  if (had_previous) {
    fs::rename(dest, previous, ec);
    if (ec) {
      throw InputError("cannot replace output folder " + destination_ + " (" + ec.message() +
                       "); this run's results are in " + staging_);
    }
  }
  fs::rename(staging, dest, ec);
  if (ec) {
    const std::string why = ec.message();
    if (had_previous) fs::rename(previous, dest, ec);
    throw InputError("cannot move this run's results into " + destination_ + " (" + why +
                     "); they are in " + staging_);
  }
  committed_ = true;
  if (had_previous) fs::remove_all(previous, ec);
}

}  // namespace vs
