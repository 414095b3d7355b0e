// Whole-file text output shared by the run writers: one place that turns an I/O failure into an
// InputError naming the file (an unwritable output folder is a user error, not a crash).
#pragma once

#include <string>

namespace vs {

// Creates or truncates `path` and writes `content` verbatim (binary mode: "\n" on every system).
void write_text_file(const std::string& path, const std::string& content);

}  // namespace vs
