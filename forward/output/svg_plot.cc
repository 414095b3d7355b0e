#include "output/svg_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>

#include "core/error.h"
#include "output/plot_ticks.h"

namespace vs {
namespace {

constexpr double kLeft = 80.0;
constexpr double kRight = 24.0;
constexpr double kTop = 44.0;
constexpr double kBottom = 56.0;
constexpr double kLegendRow = 18.0;
constexpr double kCharWidth = 7.0;  // rough width of a 12 px sans-serif character
constexpr int kTargetTicks = 6;
constexpr double kTitleMarginPx = 8.0;  // free space left and right of the title
constexpr double kCharWidthPerFontPx = 0.6;

// Greedy word wrap into lines of at most `max_chars` characters; a word longer than a line is
// broken inside.
std::vector<std::string> wrap_words(std::string_view text, std::size_t max_chars) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t pos = 0;
  while (pos < text.size()) {
    while (pos < text.size() && text[pos] == ' ') ++pos;
    if (pos >= text.size()) break;
    std::size_t end = text.find(' ', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view word = text.substr(pos, end - pos);
    pos = end;
    while (!word.empty()) {
      const std::size_t room =
          line.empty() ? max_chars : max_chars - std::min(max_chars, line.size() + 1);
      if (word.size() <= room) {
        if (!line.empty()) line += ' ';
        line += word;
        word = {};
      } else if (!line.empty()) {
        lines.push_back(line);
        line.clear();
      } else {
        lines.emplace_back(word.substr(0, max_chars));
        word.remove_prefix(max_chars);
      }
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

// Coordinates with two decimals: a hundredth of a pixel is invisible and keeps files stable.
std::string px(double value) {
  if (std::abs(value) < 0.005) value = 0.0;  // no "-0.00"
  return fmt::format("{:.2f}", value);
}

bool finite_point(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

std::size_t point_count(const PlotSeries& s) { return std::min(s.x.size(), s.y.size()); }

struct DataBox {
  double x_lo = std::numeric_limits<double>::infinity();
  double x_hi = -std::numeric_limits<double>::infinity();
  double y_lo = std::numeric_limits<double>::infinity();
  double y_hi = -std::numeric_limits<double>::infinity();
  bool empty = true;
};

DataBox data_box(const std::vector<PlotSeries>& series) {
  DataBox box;
  for (const PlotSeries& s : series) {
    for (std::size_t i = 0; i < point_count(s); ++i) {
      if (!finite_point(s.x[i], s.y[i])) continue;
      box.x_lo = std::min(box.x_lo, s.x[i]);
      box.x_hi = std::max(box.x_hi, s.x[i]);
      box.y_lo = std::min(box.y_lo, s.y[i]);
      box.y_hi = std::max(box.y_hi, s.y[i]);
      box.empty = false;
    }
  }
  return box;
}

AxisRange axis_range(const std::optional<AxisRange>& fixed, double lo, double hi, bool empty) {
  if (fixed && std::isfinite(fixed->min) && std::isfinite(fixed->max) && fixed->max > fixed->min) {
    return *fixed;
  }
  if (empty) return {0.0, 1.0};
  const TickRange r = nice_range(lo, hi, kTargetTicks);
  return {r.lo, r.hi};
}

// Widens `range` about its centre to `span`.
void widen(AxisRange& range, double span) {
  const double centre = 0.5 * (range.min + range.max);
  range = {centre - 0.5 * span, centre + 0.5 * span};
}

struct Frame {
  double left = 0.0, top = 0.0, width = 1.0, height = 1.0;
  AxisRange x, y;
  double map_x(double v) const { return left + (v - x.min) / (x.max - x.min) * width; }
  double map_y(double v) const { return top + height - (v - y.min) / (y.max - y.min) * height; }
};

// Equal aspect: widen the auto-ranged axis so both have the same data length per pixel; when
// that axis is fixed, shrink the plot area of the other one instead.
void apply_equal_aspect(const SvgFigure& figure, Frame& frame) {
  const double ux = (frame.x.max - frame.x.min) / frame.width;
  const double uy = (frame.y.max - frame.y.min) / frame.height;
  if (ux > uy) {
    if (!figure.y_range) {
      widen(frame.y, ux * frame.height);
    } else {
      const double h = (frame.y.max - frame.y.min) / ux;
      frame.top += 0.5 * (frame.height - h);
      frame.height = h;
    }
  } else if (uy > ux) {
    if (!figure.x_range) {
      widen(frame.x, uy * frame.width);
    } else {
      const double w = (frame.x.max - frame.x.min) / uy;
      frame.left += 0.5 * (frame.width - w);
      frame.width = w;
    }
  }
}

struct Style {
  std::string colour;
  bool dashed = false;
};

Style series_style(const PlotSeries& s, std::size_t position) {
  const auto& palette = plot_palette();
  const std::size_t n = palette.size();
  const std::size_t index = s.colour >= 0 ? static_cast<std::size_t>(s.colour) : position;
  // After one round of the palette, automatic colours come back dashed so series stay distinct.
  const bool second_round = s.colour < 0 && (position / n) % 2 == 1;
  return {palette[index % n], s.dashed || second_round};
}

std::string stroke_attributes(const Style& style, double width) {
  std::string a =
      fmt::format(R"svg(fill="none" stroke="{}" stroke-width="{}")svg", style.colour, px(width));
  if (style.dashed) a += R"svg( stroke-dasharray="6 3")svg";
  return a;
}

// Slack in pixels so that data exactly on a fixed range end is not lost to round-off.
constexpr double kEdgePx = 0.01;

bool inside(const Frame& f, double x, double y) {
  return x >= f.left - kEdgePx && x <= f.left + f.width + kEdgePx && y >= f.top - kEdgePx &&
         y <= f.top + f.height + kEdgePx;
}

void append_dot(std::string& out, double x, double y, double radius, const Style& style) {
  out += fmt::format(R"svg(<circle cx="{}" cy="{}" r="{}" fill="{}"/>)svg", px(x), px(y),
                     px(radius), style.colour);
  out += '\n';
}

void append_markers(std::string& out, const PlotSeries& s, const Style& style, const Frame& f) {
  for (std::size_t i = 0; i < point_count(s); ++i) {
    if (!finite_point(s.x[i], s.y[i])) continue;
    const double x = f.map_x(s.x[i]);
    const double y = f.map_y(s.y[i]);
    if (inside(f, x, y)) append_dot(out, x, y, s.marker_radius_px, style);
  }
}

// Liang-Barsky: the part [t0, t1] of the segment a + t (b - a), t in [0, 1], inside the frame.
bool clip_segment(const Frame& f, double ax, double ay, double bx, double by, double& t0,
                  double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const double dx = bx - ax;
  const double dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {ax - f.left, f.left + f.width - ax, ay - f.top, f.top + f.height - ay};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < -kEdgePx) return false;  // parallel to this edge and outside
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

// Lines are clipped to the plot area here rather than with an SVG clipPath, which several
// viewers (ImageMagick among them) render wrongly.
void append_lines(std::string& out, const PlotSeries& s, const Style& style, const Frame& f) {
  std::vector<std::string> piece;
  auto flush = [&] {
    if (piece.size() > 1) {
      out +=
          R"svg(<polyline )svg" + stroke_attributes(style, s.line_width_px) + R"svg( points=")svg";
      for (std::size_t k = 0; k < piece.size(); ++k) {
        if (k > 0) out += ' ';
        out += piece[k];
      }
      out += "\"/>\n";
    }
    piece.clear();
  };
  auto point = [](double x, double y) { return px(x) + ',' + px(y); };
  const std::size_t n = point_count(s);
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite_point(s.x[i], s.y[i])) continue;
    const double ax = f.map_x(s.x[i]);
    const double ay = f.map_y(s.y[i]);
    const bool next_finite = i + 1 < n && finite_point(s.x[i + 1], s.y[i + 1]);
    const bool previous_finite = i > 0 && finite_point(s.x[i - 1], s.y[i - 1]);
    if (!next_finite) {
      // An isolated point would vanish as a polyline: show it as a dot.
      if (!previous_finite && inside(f, ax, ay)) append_dot(out, ax, ay, s.marker_radius_px, style);
      flush();
      continue;
    }
    const double bx = f.map_x(s.x[i + 1]);
    const double by = f.map_y(s.y[i + 1]);
    double t0 = 0.0;
    double t1 = 1.0;
    if (!clip_segment(f, ax, ay, bx, by, t0, t1)) {
      flush();
      continue;
    }
    if (t0 > 0.0 || piece.empty()) {
      flush();
      piece.push_back(point(ax + t0 * (bx - ax), ay + t0 * (by - ay)));
    }
    piece.push_back(point(ax + t1 * (bx - ax), ay + t1 * (by - ay)));
    if (t1 < 1.0) flush();
  }
  flush();
}

void append_axes(std::string& out, const SvgFigure& figure, const Frame& f) {
  const std::vector<double> xt = nice_ticks(f.x.min, f.x.max, kTargetTicks);
  const std::vector<double> yt = nice_ticks(f.y.min, f.y.max, kTargetTicks);
  const double x_step = xt.size() > 1 ? xt[1] - xt[0] : f.x.max - f.x.min;
  const double y_step = yt.size() > 1 ? yt[1] - yt[0] : f.y.max - f.y.min;
  const std::string bottom = px(f.top + f.height);
  out += "<g stroke=\"#dddddd\" stroke-width=\"1\">\n";
  for (double t : xt) {
    const std::string x = px(f.map_x(t));
    out +=
        fmt::format(R"svg(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)svg", x, px(f.top), bottom);
    out += '\n';
  }
  for (double t : yt) {
    const std::string y = px(f.map_y(t));
    out += fmt::format(R"svg(<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>)svg", y, px(f.left),
                       px(f.left + f.width));
    out += '\n';
  }
  out += "</g>\n";
  out += fmt::format(
      R"svg(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#333333"/>)svg",
      px(f.left), px(f.top), px(f.width), px(f.height));
  out += "\n<g font-size=\"12\" fill=\"#333333\">\n";
  for (double t : xt) {
    out +=
        fmt::format(R"svg(<text x="{}" y="{}" text-anchor="middle">{}</text>)svg", px(f.map_x(t)),
                    px(f.top + f.height + 16.0), xml_escape(format_tick(t, x_step)));
    out += '\n';
  }
  for (double t : yt) {
    out += fmt::format(R"svg(<text x="{}" y="{}" text-anchor="end">{}</text>)svg", px(f.left - 6.0),
                       px(f.map_y(t) + 4.0), xml_escape(format_tick(t, y_step)));
    out += '\n';
  }
  out += "</g>\n";
  out += fmt::format(R"svg(<text x="{}" y="{}" font-size="13" text-anchor="middle">{}</text>)svg",
                     px(f.left + 0.5 * f.width), px(f.top + f.height + 40.0),
                     xml_escape(figure.x_label));
  out += '\n';
  const double yl_x = 20.0;
  const double yl_y = f.top + 0.5 * f.height;
  out += fmt::format(
      R"svg(<text font-size="13" text-anchor="middle" transform="translate({},{}) rotate(-90)">{}</text>)svg",
      px(yl_x), px(yl_y), xml_escape(figure.y_label));
  out += '\n';
}

void append_legend(std::string& out, const SvgFigure& figure, double x, double y) {
  out += "<g font-size=\"12\" fill=\"#333333\">\n";
  for (std::size_t i = 0; i < figure.series.size(); ++i) {
    const PlotSeries& s = figure.series[i];
    if (s.label.empty()) continue;
    const Style style = series_style(s, i);
    const std::string cy = px(y);
    if (s.style != SeriesStyle::kMarkers) {
      out += fmt::format(R"svg(<line x1="{}" y1="{}" x2="{}" y2="{}" {}/>)svg", px(x), cy,
                         px(x + 24.0), cy, stroke_attributes(style, s.line_width_px));
      out += '\n';
    }
    if (s.style != SeriesStyle::kLine) {
      out += fmt::format(R"svg(<circle cx="{}" cy="{}" r="{}" fill="{}"/>)svg", px(x + 12.0), cy,
                         px(s.marker_radius_px), style.colour);
      out += '\n';
    }
    out += fmt::format(R"svg(<text x="{}" y="{}">{}</text>)svg", px(x + 30.0), px(y + 4.0),
                       xml_escape(s.label));
    out += '\n';
    y += kLegendRow;
  }
  out += "</g>\n";
}

}  // namespace

const std::vector<std::string>& plot_palette() {
  static const std::vector<std::string> palette = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                   "#E69F00", "#56B4E9", "#000000", "#F0E442"};
  return palette;
}

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

double estimated_text_width(std::string_view text, double font_px) {
  return kCharWidthPerFontPx * font_px * static_cast<double>(text.size());
}

TitleLayout layout_title(std::string_view title, double width_px) {
  TitleLayout layout;
  const double room = std::max(width_px - 2.0 * kTitleMarginPx, 1.0);
  for (double font = 15.0; font >= 9.0; font -= 1.0) {
    const auto max_chars =
        static_cast<std::size_t>(std::max(1.0, std::floor(room / (kCharWidthPerFontPx * font))));
    layout.font_px = font;
    layout.lines = wrap_words(title, max_chars);
    if (layout.lines.size() <= 2) return layout;
  }
  // Still more than two lines at the smallest size: keep two, the second cut with "...".
  const auto max_chars = static_cast<std::size_t>(
      std::max(4.0, std::floor(room / (kCharWidthPerFontPx * layout.font_px))));
  std::string second = layout.lines[1];
  for (std::size_t k = 2; k < layout.lines.size(); ++k) second += ' ' + layout.lines[k];
  layout.lines.resize(2);
  layout.lines[1] = second.substr(0, max_chars - 3) + "...";
  return layout;
}

std::string render_svg(const SvgFigure& figure) {
  std::size_t legend_entries = 0;
  std::size_t longest_label = 0;
  for (const PlotSeries& s : figure.series) {
    if (s.label.empty()) continue;
    ++legend_entries;
    longest_label = std::max(longest_label, s.label.size());
  }
  const double legend_width =
      legend_entries == 0 ? 0.0
                          : std::min(280.0, 46.0 + kCharWidth * static_cast<double>(longest_label));
  const double width = std::max(figure.width_px, 200) + legend_width;
  // Grow the figure rather than clip a long legend.
  const double legend_height = kLegendRow * static_cast<double>(legend_entries);
  const double height = std::max(static_cast<double>(std::max(figure.height_px, 150)),
                                 kTop + legend_height + kBottom);

  Frame frame;
  frame.left = kLeft;
  frame.top = kTop;
  frame.width = width - legend_width - kLeft - kRight;
  frame.height = height - kTop - kBottom;
  const DataBox box = data_box(figure.series);
  frame.x = axis_range(figure.x_range, box.x_lo, box.x_hi, box.empty);
  frame.y = axis_range(figure.y_range, box.y_lo, box.y_hi, box.empty);
  if (figure.equal_aspect) apply_equal_aspect(figure, frame);

  std::string out;
  out += fmt::format(
      R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" font-family="sans-serif">)svg",
      px(width), px(height));
  out += '\n';
  out += R"svg(<rect width="100%" height="100%" fill="#ffffff"/>)svg";
  out += '\n';
  // Each title line is centred over the plot frame, moved towards the figure's centre as far as
  // needed to keep it inside the figure.
  const TitleLayout title = layout_title(figure.title, width);
  const double line_px = 1.15 * title.font_px;
  double baseline = title.lines.size() > 1 ? 6.0 + title.font_px : 26.0;
  for (const std::string& line : title.lines) {
    const double half = 0.5 * estimated_text_width(line, title.font_px);
    const double lo = kTitleMarginPx + half, hi = width - kTitleMarginPx - half;
    const double centre =
        lo <= hi ? std::clamp(frame.left + 0.5 * frame.width, lo, hi) : 0.5 * width;
    out += fmt::format(R"svg(<text x="{}" y="{}" font-size="{}" text-anchor="middle">{}</text>)svg",
                       px(centre), px(baseline), title.font_px, xml_escape(line));
    out += '\n';
    baseline += line_px;
  }
  append_axes(out, figure, frame);
  // Data outside a fixed range is clipped to the plot area rather than drawn over the labels.
  out += "<g>\n";
  for (std::size_t i = 0; i < figure.series.size(); ++i) {
    const PlotSeries& s = figure.series[i];
    const Style style = series_style(s, i);
    if (s.style != SeriesStyle::kMarkers) append_lines(out, s, style, frame);
    if (s.style != SeriesStyle::kLine) append_markers(out, s, style, frame);
  }
  out += "</g>\n";
  if (box.empty) {
    out += fmt::format(
        R"svg(<text x="{}" y="{}" font-size="14" fill="#888888" text-anchor="middle">no data</text>)svg",
        px(frame.left + 0.5 * frame.width), px(frame.top + 0.5 * frame.height));
    out += '\n';
  }
  if (legend_entries > 0) {
    append_legend(out, figure, width - legend_width + 8.0, kTop + 10.0);
  }
  out += "</svg>\n";
  return out;
}

void write_svg(const SvgFigure& figure, const std::string& path) {
  std::ofstream file(path, std::ios::binary);
  file << render_svg(figure);
  file.close();
  if (!file) throw InputError("cannot write plot " + path);
}

}  // namespace vs
