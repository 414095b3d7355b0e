#include "scene/text_checks.h"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "core/error.h"

namespace vs {

namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";

struct Invisible {
  std::string_view bytes;
  std::string_view name;  // "U+00A0 NO-BREAK SPACE"
};

// Multi-byte UTF-8 sequences that look like nothing or like a plain space.
constexpr Invisible kInvisibleSequences[] = {
    {"\xEF\xBB\xBF", "U+FEFF BYTE ORDER MARK"},   {"\xC2\xA0", "U+00A0 NO-BREAK SPACE"},
    {"\xE2\x80\x8B", "U+200B ZERO WIDTH SPACE"},  {"\xE2\x80\x8C", "U+200C ZERO WIDTH NON-JOINER"},
    {"\xE2\x80\x8D", "U+200D ZERO WIDTH JOINER"}, {"\xE2\x80\xAF", "U+202F NARROW NO-BREAK SPACE"},
    {"\xE2\x81\xA0", "U+2060 WORD JOINER"},
};

std::string control_name(unsigned char c) {
  switch (c) {
    case 0x00:
      return "U+0000 NUL";
    case 0x09:
      return "U+0009 TAB";
    case 0x0A:
      return "U+000A LINE FEED";
    case 0x0D:
      return "U+000D CARRIAGE RETURN";
    case 0x7F:
      return "U+007F DELETE";
    default:
      return fmt::format("U+{:04X} CONTROL", static_cast<unsigned>(c));
  }
}

// Length and name of the invisible character at text[i], or {0, ""}.
std::pair<std::size_t, std::string> invisible_at(std::string_view text, std::size_t i) {
  const auto c = static_cast<unsigned char>(text[i]);
  if (c < 0x20 || c == 0x7F) return {1, control_name(c)};
  for (const Invisible& s : kInvisibleSequences) {
    if (text.substr(i, s.bytes.size()) == s.bytes) return {s.bytes.size(), std::string(s.name)};
  }
  return {0, ""};
}

}  // namespace

void check_text_input_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(fmt::format("{}: cannot open {}", path, what));
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxTextInputBytes) {
    throw InputError(fmt::format("{}: {} bytes is larger than the {} MiB a {} may have", path, size,
                                 kMaxTextInputBytes >> 20, what));
  }
}

bool valid_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = 0;
    char32_t code = 0;
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      extra = 1;
      code = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
      extra = 2;
      code = c & 0x0F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      extra = 3;
      code = c & 0x07;
    } else {
      return false;  // a continuation byte, an overlong lead (C0, C1) or beyond F4
    }
    if (i + static_cast<std::size_t>(extra) >= text.size()) return false;  // cut short
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      if ((d & 0xC0) != 0x80) return false;
      code = (code << 6) | (d & 0x3F);
    }
    if ((extra == 2 && (code < 0x800 || (code >= 0xD800 && code <= 0xDFFF))) ||
        (extra == 3 && (code < 0x10000 || code > 0x10FFFF))) {
      return false;
    }
    i += 1 + static_cast<std::size_t>(extra);
  }
  return true;
}

std::string_view trim_blanks(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::string_view strip_utf8_bom(std::string_view line) {
  if (line.substr(0, kBom.size()) == kBom) line.remove_prefix(kBom.size());
  return line;
}

std::string show_invisible(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const auto [length, name] = invisible_at(text, i);
    if (length == 0) {
      out += text[i++];
      continue;
    }
    out += fmt::format("<{}>", name);
    i += length;
  }
  return out;
}

std::string invisible_note(std::string_view text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto [length, name] = invisible_at(text, i);
    if (length > 0) return fmt::format(" (it contains {})", name);
  }
  return "";
}

}  // namespace vs
