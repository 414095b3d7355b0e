// Small helpers for line-based text inputs (measurement CSVs, flow-curve tables): a UTF-8 byte
// order mark at the start of a file is dropped, and characters a reader cannot see in an error
// message (tabs, NUL, non-breaking spaces, zero-width characters, ...) are named instead of
// printed ("U+0009 TAB").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace vs {

// Line-based input files larger than this are refused before reading (64 MiB: millions of rows,
// far beyond any measurement or flow curve).
inline constexpr std::size_t kMaxTextInputBytes = 64u << 20;

// Throws InputError if `path` is not a regular file or is larger than kMaxTextInputBytes;
// `what` names the file kind ("measurement file").
void check_text_input_file(const std::string& path, const std::string& what);

// Whether `text` is well-formed UTF-8 (no stray continuation bytes, overlong forms, surrogates or
// code points beyond U+10FFFF).
bool valid_utf8(std::string_view text);

// `s` without leading and trailing blanks (space, tab, carriage return).
std::string_view trim_blanks(std::string_view s);

// `line` without a leading UTF-8 byte order mark (EF BB BF).
std::string_view strip_utf8_bom(std::string_view line);

// `text` with every invisible or ambiguous character replaced by "<U+XXXX NAME>": control
// characters (tab, CR, NUL, ...), the byte order mark, no-break and zero-width spaces. Other
// characters are kept as they are.
std::string show_invisible(std::string_view text);

// "" if `text` has no invisible characters, else " (it contains U+0009 TAB)" naming the first.
std::string invisible_note(std::string_view text);

}  // namespace vs
