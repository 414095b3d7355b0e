// One number format for every text output (CSV, progress, summaries), so that the same run
// gives the same bytes on every machine and a CSV value reads back to nearly the same double.
#pragma once

#include <string>

namespace vs {

// Nine significant digits ("{:.9g}"): enough for mm/N/MPa data, short enough to diff.
// NaN and infinities are written as "nan", "inf", "-inf".
std::string format_number(double value);

}  // namespace vs
