// A small table of strings written as CSV, as a Markdown table and as aligned console text, plus
// the machine description and command-line helpers every study prints. Header-only.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace vsx {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }

  std::string csv() const {
    std::string s;
    auto line = [&s](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const bool quote = cells[i].find_first_of(",\"") != std::string::npos;
        std::string c = cells[i];
        if (quote) {
          std::string q;
          for (char ch : c) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
          c = "\"" + q + "\"";
        }
        s += (i ? "," : "") + c;
      }
      s += "\n";
    };
    line(header);
    for (const auto& r : rows) line(r);
    return s;
  }

  std::string markdown() const {
    std::string s = "|";
    for (const auto& h : header) s += " " + h + " |";
    s += "\n|";
    for (std::size_t i = 0; i < header.size(); ++i) s += "---|";
    s += "\n";
    for (const auto& r : rows) {
      s += "|";
      for (const auto& c : r) s += " " + c + " |";
      s += "\n";
    }
    return s;
  }

  std::string text() const {
    std::vector<std::size_t> w(header.size(), 0);
    for (std::size_t i = 0; i < header.size(); ++i) w[i] = header[i].size();
    for (const auto& r : rows) {
      for (std::size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
    }
    std::string s;
    auto line = [&](const std::vector<std::string>& cells) {
      for (std::size_t i = 0; i < cells.size() && i < w.size(); ++i) {
        s += fmt::format("{:>{}}  ", cells[i], w[i]);
      }
      s += "\n";
    };
    line(header);
    for (const auto& r : rows) line(r);
    return s;
  }
};

inline void write_text(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << text;
}

inline std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// Number formatting for tables: 4 significant digits, "-" for NaN.
inline std::string g4(double v) { return v == v ? fmt::format("{:.4g}", v) : std::string("-"); }
inline std::string pct(double v) {
  return v == v ? fmt::format("{:.3g}%", 100.0 * v) : std::string("-");
}
inline std::string ms(double s) { return fmt::format("{:.1f}", 1e3 * s); }

// "nproc N, CPU model" from the standard library and /proc/cpuinfo.
inline std::string machine_description() {
  std::string model = "unknown CPU";
  std::ifstream f("/proc/cpuinfo");
  for (std::string line; std::getline(f, line);) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return fmt::format("nproc {}, {}", std::thread::hardware_concurrency(), model);
}

// The 1-minute load average from /proc/loadavg ("?" if unavailable).
inline std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string first;
  return (f >> first) ? first : std::string("?");
}

// Command-line flags shared by the studies: --quick, --out DIR.
struct StudyArgs {
  bool quick = false;
  std::string out_dir;
  // --set KEY=VALUE (repeatable): scene overrides added to every run of studies that take them.
  std::vector<std::pair<std::string, std::string>> sets;
  // --steps A,B,...: the travel steps a study sweeps, where it sweeps them (empty: its own).
  std::vector<double> steps;
};

inline StudyArgs parse_args(int argc, char** argv, const std::string& default_out) {
  StudyArgs a;
  a.out_dir = default_out;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--quick") {
      a.quick = true;
    } else if (s == "--out" && i + 1 < argc) {
      a.out_dir = argv[++i];
    } else if (s == "--steps" && i + 1 < argc) {
      std::stringstream list(argv[++i]);
      for (std::string item; std::getline(list, item, ',');) a.steps.push_back(std::stod(item));
    } else if (s == "--set" && i + 1 < argc &&
               std::string(argv[i + 1]).find('=') != std::string::npos) {
      const std::string kv = argv[++i];
      const std::size_t eq = kv.find('=');
      a.sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else {
      std::cerr << "usage: " << argv[0]
                << " [--quick] [--out DIR] [--steps A,B,..] [--set KEY=VALUE ...]\n";
      std::exit(2);
    }
  }
  return a;
}

}  // namespace vsx
