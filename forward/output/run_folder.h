// An output folder that always describes exactly one run (issue 16): a run writes into a staging
// folder beside its destination, and commit() swaps it in only when everything is written. The
// previous run's folder is kept untouched until then (a crash, a stopped process or a write
// failure part-way never truncates it, and never mixes two runs' files); after the swap it is
// removed whole, so no file of an older run (profiles at other travels, an old fit) survives.
//
// The destination must be new, empty, or a folder this program wrote (it holds `owner_file`:
// run.json for `vshell run`, calibration.json for `vshell calibrate`): a folder with other
// contents is refused before any work, so a mistyped -o never deletes a user's files.
#pragma once

#include <string>

namespace vs {

class RunFolder {
 public:
  // Throws InputError if `destination` cannot be used (see above) or the staging folder cannot
  // be created.
  RunFolder(const std::string& destination, const std::string& owner_file);
  // Removes an uncommitted staging folder only if it is empty; a partial one stays beside the
  // destination for inspection (its name says so).
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  // Where the run writes.
  const std::string& path() const { return staging_; }
  const std::string& destination() const { return destination_; }
  // Replaces the destination by the staging folder. Throws InputError if a rename fails (the
  // previous folder is then restored when possible).
  void commit();

 private:
  std::string destination_, staging_;
  bool committed_ = false;
};

}  // namespace vs
