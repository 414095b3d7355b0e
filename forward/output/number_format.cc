#include "output/number_format.h"

#include <fmt/format.h>

namespace vs {

std::string format_number(double value) { return fmt::format("{:.9g}", value); }

}  // namespace vs
