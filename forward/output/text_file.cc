#include "output/text_file.h"

#include <fstream>

#include "core/error.h"

namespace vs {

void write_text_file(const std::string& path, const std::string& content) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw InputError("cannot open " + path + " for writing");
  file << content;
  file.close();
  if (!file) throw InputError("cannot write " + path);
}

}  // namespace vs
