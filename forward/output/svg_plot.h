// A small, dependency-free SVG line/scatter plot writer for run folders: title, axis labels with
// units, 1-2-5 ticks, several series with a legend, a colour-blind-safe palette (Okabe & Ito),
// optional fixed ranges and equal aspect (for deformed shapes). Output is deterministic: the
// same figure gives the same bytes (fixed-precision coordinates, no timestamps, no ids).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vs {

enum class SeriesStyle {
  kLine,     // polyline; a NaN/inf point breaks the line into separate pieces
  kMarkers,  // a dot per point; NaN/inf points are skipped
  kLineAndMarkers,
};

struct PlotSeries {
  std::string label;  // legend entry; empty keeps the series out of the legend
  std::vector<double> x;
  std::vector<double> y;  // points beyond the shorter of x and y are ignored
  SeriesStyle style = SeriesStyle::kLine;
  int colour = -1;      // palette index (wraps); -1 = the series' position among the series
  bool dashed = false;  // tells apart series that share a colour
  double line_width_px = 1.5;
  double marker_radius_px = 2.5;
};

struct AxisRange {
  double min = 0.0;
  double max = 1.0;
};

struct SvgFigure {
  std::string title;
  std::string x_label;  // with unit, e.g. "punch travel [mm]"
  std::string y_label;
  std::optional<AxisRange> x_range;  // fixed range; otherwise the data widened to nice ticks
  std::optional<AxisRange> y_range;
  // Same data length per pixel on both axes (the auto ranges are widened to achieve it), so a
  // deformed meridian shows its true shape.
  bool equal_aspect = false;
  int width_px = 720;
  int height_px = 480;
  std::vector<PlotSeries> series;
};

// The palette, in the order series take it (Okabe & Ito 2008; yellow last, it is faint on white).
const std::vector<std::string>& plot_palette();

// Escapes & < > " ' for text and attribute values.
std::string xml_escape(std::string_view text);

// The title of a figure `width_px` wide, laid out so that no line runs off either side: wrapped
// at spaces into at most two lines at 15 px; a title that still does not fit is set smaller
// (down to 9 px), and only beyond that its second line is cut with "...". Widths are estimated
// at 0.6 font sizes per character (wider than the average sans-serif character).
struct TitleLayout {
  double font_px = 15.0;
  std::vector<std::string> lines;  // empty for an empty title
};
TitleLayout layout_title(std::string_view title, double width_px);

// Estimated width of `text` set at `font_px` (the rule of layout_title).
double estimated_text_width(std::string_view text, double font_px);

// The SVG document for `figure`.
std::string render_svg(const SvgFigure& figure);

// Writes render_svg(figure) to `path`; throws InputError if the file cannot be written.
void write_svg(const SvgFigure& figure, const std::string& path);

}  // namespace vs
