#include "output/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "output/plot_ticks.h"

namespace vs {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
    ++n;
  return n;
}

TEST(NiceTicks, StepsAreOneTwoFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_tick_step(0.0, 10.0, 5), 2.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.0, 1.0, 5), 0.2);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.0, 30.0, 6), 5.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(0.0, 70.0, 6), 10.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(-0.003, 0.004, 7), 0.001);
}

TEST(NiceTicks, TicksLieInsideTheRangeAndIncludeExactEnds) {
  const std::vector<double> t = nice_ticks(0.0, 10.0, 5);
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_EQ(t.back(), 10.0);
  const std::vector<double> u = nice_ticks(-3.7, 12.1, 6);
  ASSERT_FALSE(u.empty());
  EXPECT_GE(u.front(), -3.7);
  EXPECT_LE(u.back(), 12.1);
  EXPECT_TRUE(nice_ticks(1.0, 1.0).empty());
  EXPECT_TRUE(nice_ticks(0.0, std::numeric_limits<double>::quiet_NaN()).empty());
}

TEST(NiceTicks, RangeWidensToTicksAndHandlesAFlatLine) {
  const TickRange r = nice_range(0.3, 9.4, 5);
  EXPECT_DOUBLE_EQ(r.lo, 0.0);
  EXPECT_DOUBLE_EQ(r.hi, 10.0);
  const TickRange flat = nice_range(5.0, 5.0, 5);
  EXPECT_LT(flat.lo, 5.0);
  EXPECT_GT(flat.hi, 5.0);
  const TickRange zero = nice_range(0.0, 0.0, 5);
  EXPECT_LT(zero.lo, 0.0);
  EXPECT_GT(zero.hi, 0.0);
}

TEST(NiceTicks, LabelsUseTheDecimalsOfTheStep) {
  EXPECT_EQ(format_tick(0.4, 0.2), "0.4");
  EXPECT_EQ(format_tick(10.0, 2.0), "10");
  EXPECT_EQ(format_tick(-0.0, 0.05), "0.00");
  EXPECT_EQ(format_tick(-1e-18, 0.1), "0.0");
  EXPECT_EQ(format_tick(0.015, 0.005), "0.015");
}

TEST(SvgPlot, EscapesXml) {
  EXPECT_EQ(xml_escape(R"(a<b & "c" 'd'>)"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  SvgFigure f;
  f.title = "force <N> & travel";
  f.x_label = "x \"mm\"";
  PlotSeries s;
  s.label = "a<b";
  s.x = {0.0, 1.0};
  s.y = {0.0, 1.0};
  f.series.push_back(s);
  const std::string svg = render_svg(f);
  EXPECT_NE(svg.find("force &lt;N&gt; &amp; travel"), std::string::npos);
  EXPECT_NE(svg.find("x &quot;mm&quot;"), std::string::npos);
  EXPECT_NE(svg.find("a&lt;b"), std::string::npos);
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
}

SvgFigure sample_figure() {
  SvgFigure f;
  f.title = "sample";
  f.x_label = "punch travel [mm]";
  f.y_label = "punch force [kN]";
  for (int k = 0; k < 3; ++k) {
    PlotSeries s;
    s.label = "series " + std::to_string(k);
    for (int i = 0; i <= 20; ++i) {
      s.x.push_back(0.5 * i);
      s.y.push_back(std::sin(0.3 * i + k));
    }
    s.style = k == 2 ? SeriesStyle::kMarkers : SeriesStyle::kLine;
    f.series.push_back(s);
  }
  return f;
}

TEST(SvgPlot, SameFigureGivesSameBytes) {
  const std::string a = render_svg(sample_figure());
  const std::string b = render_svg(sample_figure());
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.rfind("<svg", 0), 0u);
  EXPECT_EQ(a.substr(a.size() - 7), "</svg>\n");
  EXPECT_EQ(count(a, "<polyline"), 2u);
  EXPECT_EQ(count(a, "<circle"), 21u + 1u);  // 21 markers + 1 legend marker
  EXPECT_NE(a.find(plot_palette()[0]), std::string::npos);
  EXPECT_NE(a.find(plot_palette()[1]), std::string::npos);
}

TEST(SvgPlot, NonFinitePointsAreSkippedAndBreakLines) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  SvgFigure f;
  PlotSeries s;
  s.x = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  s.y = {0.0, 1.0, nan, 3.0, 4.0, inf};
  f.series.push_back(s);
  const std::string svg = render_svg(f);
  EXPECT_EQ(count(svg, "<polyline"), 2u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, EmptyFigureSaysNoData) {
  SvgFigure f;
  f.series.emplace_back();
  const std::string svg = render_svg(f);
  EXPECT_NE(svg.find("no data"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

// Extracts the plotted polyline's points as numbers.
std::vector<double> polyline_numbers(const std::string& svg) {
  const std::size_t start = svg.find("points=\"", svg.find("<polyline")) + 8;
  const std::string points = svg.substr(start, svg.find('"', start) - start);
  std::vector<double> v;
  std::string token;
  for (char c : points + ' ') {
    if (c == ',' || c == ' ') {
      v.push_back(std::stod(token));
      token.clear();
    } else {
      token += c;
    }
  }
  return v;
}

TEST(SvgPlot, EqualAspectGivesSamePixelsPerMillimetre) {
  SvgFigure f;
  f.equal_aspect = true;
  PlotSeries s;
  // A 40 x 10 mm right angle: horizontal leg then vertical leg.
  s.x = {0.0, 40.0, 40.0};
  s.y = {0.0, 0.0, 10.0};
  f.series.push_back(s);
  const std::vector<double> p = polyline_numbers(render_svg(f));
  ASSERT_EQ(p.size(), 6u);
  const double horizontal_px = p[2] - p[0];
  const double vertical_px = p[3] - p[5];
  EXPECT_NEAR(horizontal_px / vertical_px, 4.0, 0.01);
}

// All numbers of all polylines, as x, y pairs.
std::vector<double> all_polyline_numbers(std::string svg) {
  std::vector<double> all;
  for (std::size_t pos = svg.find("<polyline"); pos != std::string::npos;
       pos = svg.find("<polyline")) {
    svg = svg.substr(pos);
    const std::vector<double> v = polyline_numbers(svg);
    all.insert(all.end(), v.begin(), v.end());
    svg = svg.substr(1);
  }
  return all;
}

TEST(SvgPlot, FixedRangeIsKeptAndLinesAreClippedToIt) {
  SvgFigure f;
  f.x_range = AxisRange{0.0, 5.0};
  f.y_range = AxisRange{-1.0, 1.0};
  PlotSeries s;
  s.x = {-1.0, 2.5, 10.0};
  s.y = {0.0, 0.5, 3.0};
  f.series.push_back(s);
  PlotSeries outside;
  outside.style = SeriesStyle::kMarkers;
  outside.x = {7.0, 2.0};
  outside.y = {0.0, 5.0};
  f.series.push_back(outside);
  const std::string svg = render_svg(f);
  EXPECT_NE(svg.find(">5<"), std::string::npos);
  EXPECT_EQ(svg.find(">10<"), std::string::npos);
  EXPECT_EQ(svg.find("<circle"), std::string::npos);  // both markers lie outside the range
  // The frame is 80 px from the left and 720 - 80 - 24 px wide; y from 44 over 480 - 44 - 56.
  const std::vector<double> p = all_polyline_numbers(svg);
  ASSERT_EQ(p.size(), 6u);  // entry point, the inside point, exit point
  EXPECT_DOUBLE_EQ(p[0], 80.0);
  for (std::size_t i = 0; i < p.size(); i += 2) {
    EXPECT_GE(p[i], 80.0);
    EXPECT_LE(p[i], 80.0 + 616.0);
    EXPECT_GE(p[i + 1], 44.0);
    EXPECT_LE(p[i + 1], 44.0 + 380.0);
  }
  EXPECT_DOUBLE_EQ(p[5], 44.0);  // leaves through the top
}

// Title lines as (x, font size, text), from the <text ... font-size="F" text-anchor="middle">
// elements at the top of the figure (y < 44, above the plot frame).
struct TitleLine {
  double x = 0.0, font = 0.0;
  std::string text;
};
std::vector<TitleLine> title_lines(const std::string& svg) {
  std::vector<TitleLine> lines;
  for (std::size_t pos = svg.find("<text x=\""); pos != std::string::npos;
       pos = svg.find("<text x=\"", pos + 1)) {
    const std::size_t end = svg.find("</text>", pos);
    const std::string element = svg.substr(pos, end - pos);
    const double y = std::stod(element.substr(element.find(" y=\"") + 4));
    if (y >= 44.0 || element.find("text-anchor=\"middle\"") == std::string::npos) continue;
    TitleLine line;
    line.x = std::stod(element.substr(9));
    line.font = std::stod(element.substr(element.find("font-size=\"") + 11));
    line.text = element.substr(element.find('>') + 1);
    lines.push_back(line);
  }
  return lines;
}

TEST(SvgPlot, ShortTitleIsOneLineAtFullSize) {
  SvgFigure f = sample_figure();
  f.title = "ex1: punch force";
  const std::vector<TitleLine> lines = title_lines(render_svg(f));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].text, "ex1: punch force");
  EXPECT_EQ(lines[0].font, 15.0);
}

TEST(SvgPlot, LongTitlesStayInsideTheFigure) {
  // Before: one line centred over the plot frame; a 150-character title started at x < 0.
  const std::string words =
      "Paper example 1, hemispherical stretching of a pinned blank on the Ghosh-Hecker geometry "
      "with Coulomb friction 0.2 and a Swift steel: forming limit diagram";
  for (const std::string& title :
       {words, words + " " + words + " " + words, std::string(300, 'x')}) {
    SvgFigure f = sample_figure();
    f.title = title;
    const std::string svg = render_svg(f);
    const double width = std::stod(svg.substr(svg.find("width=\"") + 7));
    const std::vector<TitleLine> lines = title_lines(svg);
    ASSERT_GE(lines.size(), 1u) << title;
    ASSERT_LE(lines.size(), 2u) << title;
    std::string joined;
    for (const TitleLine& line : lines) {
      const double half = 0.5 * estimated_text_width(line.text, line.font);
      EXPECT_GE(line.x - half, 0.0) << line.text;
      EXPECT_LE(line.x + half, width) << line.text;
      EXPECT_GE(line.font, 9.0);
      joined += (joined.empty() ? "" : " ") + line.text;
    }
    if (title == words) {
      EXPECT_EQ(joined, words);  // wrapped, nothing lost
    }
  }
}

TEST(SvgPlot, TitleLayoutWrapsThenShrinksThenCuts) {
  const TitleLayout one = layout_title("a b c", 720.0);
  EXPECT_EQ(one.lines, std::vector<std::string>{"a b c"});
  // 704 px at 0.6 x 15 px per character: 78 characters a line.
  const std::string two_lines = std::string(70, 'a') + " " + std::string(70, 'b');
  const TitleLayout two = layout_title(two_lines, 720.0);
  EXPECT_EQ(two.font_px, 15.0);
  EXPECT_EQ(two.lines, (std::vector<std::string>{std::string(70, 'a'), std::string(70, 'b')}));
  const TitleLayout smaller = layout_title(two_lines + " " + std::string(70, 'c'), 720.0);
  EXPECT_LT(smaller.font_px, 15.0);
  EXPECT_EQ(smaller.lines.size(), 2u);
  const TitleLayout cut = layout_title(std::string(2000, 'z'), 720.0);
  EXPECT_EQ(cut.font_px, 9.0);
  ASSERT_EQ(cut.lines.size(), 2u);
  EXPECT_EQ(cut.lines[1].substr(cut.lines[1].size() - 3), "...");
  EXPECT_TRUE(layout_title("", 720.0).lines.empty());
}

}  // namespace
}  // namespace vs
