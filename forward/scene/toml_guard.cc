#include "scene/toml_guard.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "core/error.h"

namespace vs {

namespace {

// A lexical walk over TOML text that tracks how deep the value being written sits: the segments
// of the current [header] plus, inside it, the dotted-key segments and the open arrays and inline
// tables. It does not check the syntax (toml++ does, afterwards); malformed text can only make it
// count a few levels too many or too few, never recurse or loop.
class NestingScanner {
 public:
  NestingScanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  void run() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        line_has_content_ = false;
        if (containers_.empty()) {
          key_dots_ = 0;
          in_value_ = false;
        }
        ++pos_;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
        continue;
      }
      const bool statement_start = !line_has_content_ && containers_.empty();
      line_has_content_ = true;
      if (c == '#') {
        skip_comment();
      } else if (c == '"' || c == '\'') {
        skip_string();
      } else if (c == '[' && statement_start) {
        read_header();
      } else if (c == '[' || c == '{') {
        open(c == '[' ? Container::kArray : Container::kInlineTable);
      } else if (c == ']' || c == '}') {
        if (!containers_.empty()) containers_.pop_back();
        key_dots_ = 0;
        in_value_ = true;  // the closed container was a value of the enclosing key or array
        ++pos_;
      } else if (c == ',') {
        key_dots_ = 0;
        in_value_ = !containers_.empty() && containers_.back().kind == Container::kArray;
        ++pos_;
      } else if (c == '=') {
        in_value_ = true;
        ++pos_;
      } else if (c == '.' && !in_value_) {
        ++key_dots_;
        check(base() + key_dots_ + 1);
        ++pos_;
      } else {
        ++pos_;
      }
    }
  }

 private:
  struct Container {
    enum Kind { kArray, kInlineTable } kind;
    int depth;
  };

  // Depth of the table whose keys are being written: the innermost open container, or the last
  // [header] at the top level.
  int base() const { return containers_.empty() ? header_depth_ : containers_.back().depth; }

  void check(int depth) const {
    if (depth <= kMaxTomlNesting) return;
    throw InputError(fmt::format(
        "{}:{}: nested deeper than {} levels (dotted keys, [table] headers, arrays and inline "
        "tables together); no scene or calibration file needs more than 6",
        source_, line_, kMaxTomlNesting));
  }

  void open(Container::Kind kind) {
    const int depth = base() + (in_value_ ? key_dots_ + 1 : 1);
    check(depth);
    containers_.push_back({kind, depth});
    key_dots_ = 0;
    in_value_ = kind == Container::kArray;
    ++pos_;
  }

  // [a.b.c] or [[a.b.c]]: its segments set the depth of the keys below it.
  void read_header() {
    ++pos_;
    int extra = 1;
    if (pos_ < text_.size() && text_[pos_] == '[') {
      ++pos_;
      extra = 2;  // an array of tables: the array and its table
    }
    int dots = 0;
    while (pos_ < text_.size() && text_[pos_] != ']' && text_[pos_] != '\n') {
      const char c = text_[pos_];
      if (c == '"' || c == '\'') {
        skip_string();
        continue;
      }
      if (c == '.') {
        ++dots;
        check(dots + extra);
      }
      ++pos_;
    }
    for (int i = 0; i < extra && pos_ < text_.size() && text_[pos_] == ']'; ++i) ++pos_;
    header_depth_ = dots + extra;
    key_dots_ = 0;
    in_value_ = false;
  }

  void skip_comment() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  // "basic", 'literal', """multi-line""" or '''multi-line'''; an unterminated string ends at the
  // end of its line (single-line) or of the text (multi-line), as far as the scan is concerned.
  void skip_string() {
    const char quote = text_[pos_];
    const bool multi = text_.substr(pos_, 3) == std::string(3, quote);
    pos_ += multi ? 3 : 1;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\\' && quote == '"') {
        if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++line_;
        pos_ += 2;
        continue;
      }
      if (c == '\n') {
        if (!multi) return;
        ++line_;
      }
      if (c == quote) {
        if (!multi) {
          ++pos_;
          return;
        }
        if (text_.substr(pos_, 3) == std::string(3, quote)) {
          pos_ += 3;
          while (pos_ < text_.size() && text_[pos_] == quote) ++pos_;  // """a"""" ends in a quote
          return;
        }
      }
      ++pos_;
    }
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool line_has_content_ = false;
  int header_depth_ = 0;
  int key_dots_ = 0;
  bool in_value_ = false;
  std::vector<Container> containers_;
};

std::string one_line(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return out;
}

}  // namespace

void check_toml_text(std::string_view text, const std::string& source) {
  if (text.size() > kMaxTomlBytes) {
    throw InputError(
        fmt::format("{}: {} bytes is larger than the {} MiB a scene or calibration "
                    "file may have",
                    source, text.size(), kMaxTomlBytes >> 20));
  }
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(nul), '\n');
    throw InputError(
        fmt::format("{}:{}: NUL byte (U+0000): this is not a text file", source, line));
  }
  NestingScanner(text, source).run();
}

toml::table parse_toml_text(std::string_view text, const std::string& source) {
  check_toml_text(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const toml::source_position& at = e.source().begin;
    throw InputError(
        fmt::format("{}:{}:{}: {}", source, at.line, at.column, one_line(e.description())));
  }
}

toml::table parse_toml_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(fmt::format("cannot open {} '{}'", what, path));
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxTomlBytes) {
    throw InputError(
        fmt::format("{}: {} bytes is larger than the {} MiB a scene or calibration "
                    "file may have",
                    path, size, kMaxTomlBytes >> 20));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("cannot open {} '{}'", what, path));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_toml_text(text.str(), path);
}

}  // namespace vs
