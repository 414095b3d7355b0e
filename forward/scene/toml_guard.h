// Bounds on TOML text checked before it reaches toml++. The parser and the node destructors
// recurse once per nesting level, so a key or table header nested tens of thousands of levels
// deep ("a.a.a...", "[a.a.a...]") overflows the stack: a signal instead of a message. The guard
// scans the text lexically (strings and comments skipped) and rejects, with FILE:LINE, any nesting
// deeper than kMaxTomlNesting (dotted-key and header segments, arrays and inline tables counted
// together), any file larger than kMaxTomlBytes, and NUL bytes.
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace vs {

// No project file nests deeper than 6 (material.hardening.table = [[strain, stress], ...]).
inline constexpr int kMaxTomlNesting = 64;
// Scenes and calibration configs are a few kB; an inline hardening table of 100 000 points is
// about 3 MB.
inline constexpr std::size_t kMaxTomlBytes = 16u << 20;

// Throws InputError("SOURCE:LINE: ...") if `text` breaks one of the bounds above.
void check_toml_text(std::string_view text, const std::string& source);

// Reads `path` (at most kMaxTomlBytes) and parses it after check_toml_text; syntax errors become
// InputError "PATH:LINE:COL: description" on one line. `what` names the file kind in the
// "cannot open" message ("scene file", "calibration config").
toml::table parse_toml_file(const std::string& path, const std::string& what);

// Parses in-memory text (same checks); `source` names it in messages.
toml::table parse_toml_text(std::string_view text, const std::string& source);

}  // namespace vs
