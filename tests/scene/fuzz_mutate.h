// Random edits of TOML text for the fuzz-style tests (tests/scene/fuzz_input_test.cc,
// tests/inverse/calibration_fuzz_test.cc): deterministic for a given generator state.
#pragma once

#include <random>
#include <string>
#include <vector>

namespace vs::testing {

// `s` repeated `n` times.
inline std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// One to four edits: byte deletions, insertions of TOML-significant characters and fragments,
// duplicated lines, truncation, a number replaced by an extreme one.
inline std::string mutate_toml(std::string text, std::mt19937& rng) {
  // clang-format off
  static const std::vector<std::string> kInserts = {
      "[", "]", "{", "}", "=", ".", ",", "\"", "'", "#", "\n", "\t", "\\", "-", "+", "e", "_",
      "0", "9", "inf", "nan", "1e308", "-1", "1e-320", "9223372036854775807", "\xEF\xBB\xBF",
      "\xC2\xA0", "[[tool]]\n", "[a.b.c]\n", "\"\"\"", "'''", "true", "1979-05-27T07:32:00Z"};
  static const std::vector<std::string> kNumbers = {
      "0", "-0.0", "1e308", "1e-308", "1000000000", "-5", "nan", "inf", "2147483648", "0.1",
      "65", "1e6"};
  // clang-format on
  auto pick = [&rng](std::size_t n) {
    return n == 0 ? std::size_t{0} : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const int edits = 1 + static_cast<int>(pick(4));
  for (int k = 0; k < edits && !text.empty(); ++k) {
    const std::size_t at = pick(text.size());
    switch (pick(6)) {
      case 0:
        text.erase(at, 1 + pick(8));
        break;
      case 1:
      case 2:
        text.insert(at, kInserts[pick(kInserts.size())]);
        break;
      case 3: {  // duplicate the line holding `at`
        const std::size_t newline = text.rfind('\n', at);
        const std::size_t start = newline == std::string::npos ? 0 : newline + 1;
        const std::size_t end = text.find('\n', at);
        text.insert(start, end == std::string::npos ? text.substr(start)
                                                    : text.substr(start, end - start + 1));
        break;
      }
      case 4:
        text.resize(at);
        break;
      default: {  // replace a number by an extreme one
        const std::size_t digit = text.find_first_of("0123456789", at);
        if (digit == std::string::npos) break;
        const std::size_t end = text.find_first_not_of("0123456789.e-+", digit);
        text.replace(digit, end == std::string::npos ? std::string::npos : end - digit,
                     kNumbers[pick(kNumbers.size())]);
        break;
      }
    }
  }
  return text;
}

}  // namespace vs::testing
