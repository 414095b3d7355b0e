#include "output/profile_csv.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "output/number_format.h"

namespace vs {
namespace {

std::string cell(const std::vector<double>& v, std::size_t i) {
  return i < v.size() ? format_number(v[i]) : std::string("nan");
}

std::string cell(const std::vector<int>& v, std::size_t i) {
  return i < v.size() ? fmt::format("{}", v[i]) : std::string("nan");
}

}  // namespace

double thinning_percent(double eps_thickness) { return -100.0 * std::expm1(eps_thickness); }

std::string strains_file_name(double punch_travel_mm, const std::string& line) {
  if (line == "meridian") return fmt::format("strains_travel_{:06.2f}mm.csv", punch_travel_mm);
  return fmt::format("strains_travel_{:06.2f}mm_{}.csv", punch_travel_mm, line);
}

std::string primary_line(const RunResult& result) {
  return result.profiles.empty() ? std::string("meridian") : result.profiles.front().line;
}

std::vector<const Profile*> profile_stages(const RunResult& result, const std::string& line) {
  std::vector<const Profile*> stages;
  for (const Profile& p : result.profiles) {
    if (!line.empty() && p.line != line) continue;
    const bool repeat = std::any_of(stages.begin(), stages.end(), [&](const Profile* q) {
      return q->punch_travel_mm == p.punch_travel_mm && q->line == p.line;
    });
    if (!repeat) stages.push_back(&p);
  }
  if (stages.empty() && !result.history.empty()) stages.push_back(&result.history.back());
  return stages;
}

std::size_t profile_rows(const Profile& p) {
  return std::max({p.r0_mm.size(), p.r_mm.size(), p.z_mm.size(), p.thickness_mm.size(),
                   p.eps_meridional.size(), p.eps_circumferential.size(), p.eps_thickness.size(),
                   p.eps_effective.size(), p.contact.size()});
}

std::string profile_csv(const Profile& p) {
  std::string out = fmt::format("# punch_travel_mm={}", format_number(p.punch_travel_mm));
  out += p.line == "meridian" ? std::string("\n") : fmt::format(", line={}\n", p.line);
  out +=
      "r0_mm,r_mm,z_mm,thickness_mm,eps_meridional,eps_circumferential,eps_thickness,"
      "thinning_percent,eps_effective,contact\n";
  const std::size_t n = profile_rows(p);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string thinning = i < p.eps_thickness.size()
                                     ? format_number(thinning_percent(p.eps_thickness[i]))
                                     : std::string("nan");
    out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", cell(p.r0_mm, i), cell(p.r_mm, i),
                       cell(p.z_mm, i), cell(p.thickness_mm, i), cell(p.eps_meridional, i),
                       cell(p.eps_circumferential, i), cell(p.eps_thickness, i), thinning,
                       cell(p.eps_effective, i), cell(p.contact, i));
  }
  return out;
}

}  // namespace vs
