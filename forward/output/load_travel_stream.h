// load_travel.csv written while the solver runs: one row appended and flushed per converged step,
// so a crash, a kill or a failed step keeps every earlier row on disk.
#pragma once

#include <fstream>
#include <string>

#include "core/error.h"
#include "run/run_result.h"

namespace vs {

class LoadTravelStream {
 public:
  // Creates (truncates) `path` and writes the header. Throws InputError if it cannot.
  explicit LoadTravelStream(const std::string& path);

  // Appends load_travel_csv_row(record) and flushes. Throws InputError on a write failure
  // (disk full): losing rows silently would defeat the purpose of streaming.
  void append(const StepRecord& record);

  // Closes the file (before its folder is moved, RunFolder::commit).
  void close() { file_.close(); }

  int rows_written() const { return rows_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream file_;
  int rows_ = 0;
};

}  // namespace vs
