#include "output/load_travel_stream.h"

#include "core/error.h"
#include "output/step_csv.h"

namespace vs {

LoadTravelStream::LoadTravelStream(const std::string& path)
    : path_(path), file_(path, std::ios::binary | std::ios::trunc) {
  if (!file_) throw InputError("cannot open " + path + " for writing");
  file_ << load_travel_csv_header() << '\n' << std::flush;
  if (!file_) throw InputError("cannot write " + path);
}

void LoadTravelStream::append(const StepRecord& record) {
  file_ << load_travel_csv_row(record) << '\n' << std::flush;
  if (!file_) throw InputError("cannot write " + path_);
  ++rows_;
}

}  // namespace vs
