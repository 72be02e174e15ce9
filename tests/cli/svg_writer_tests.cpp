// The SVG builder: fitting, flipping y, and escaping text.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "svg_writer.hpp"

namespace carom::cli {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

// The cy of every <circle>, in the order drawn. (Plain search, not std::regex: GCC 12 warns
// falsely inside <regex> under the sanitizers, and the asan build treats warnings as errors.)
std::vector<double> circle_heights(const std::string& svg) {
  std::vector<double> heights;
  const std::string cy = "cy=\"";
  for (std::size_t at = svg.find("<circle"); at != std::string::npos;
       at = svg.find("<circle", at + 1)) {
    const std::size_t value = svg.find(cy, at) + cy.size();
    heights.push_back(std::stod(svg.substr(value, svg.find('"', value) - value)));
  }
  return heights;
}

TEST(SvgFigure, IsAWholeDocumentOnWhite) {
  SvgFigure figure;
  figure.circle({0, 0}, 1, {});
  const std::string svg = figure.render();
  EXPECT_THAT(svg, StartsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg "));
  EXPECT_THAT(svg, HasSubstr("viewBox=\"0 0 "));
  EXPECT_THAT(svg, HasSubstr("fill=\"white\""));
  EXPECT_THAT(svg, HasSubstr("</svg>\n"));
}

TEST(SvgFigure, YPointsUp) {
  SvgFigure figure;
  figure.circle({0, 0}, 1, {});
  figure.circle({0, 10}, 1, {});
  const std::vector<double> heights = circle_heights(figure.render());
  ASSERT_EQ(heights.size(), 2u);
  EXPECT_GT(heights[0], heights[1]);  // the higher circle is nearer the top of the screen
}

TEST(SvgFigure, SameLooksAtAnyScale) {
  // A figure a million times larger renders to the same document.
  SvgFigure small;
  small.circle({0, 0}, 1e-3, {});
  small.arrow({0, 0}, {2e-3, 1e-3}, {});
  SvgFigure large;
  large.circle({0, 0}, 1e3, {});
  large.arrow({0, 0}, {2e3, 1e3}, {});
  EXPECT_EQ(small.render(), large.render());
}

TEST(SvgFigure, EscapesText) {
  SvgFigure figure;
  figure.heading("a < b & \"c\"");
  figure.label({0, 0}, {1, 0}, "x > y", "black");
  const std::string svg = figure.render();
  EXPECT_THAT(svg, HasSubstr("a &lt; b &amp; &quot;c&quot;"));
  EXPECT_THAT(svg, HasSubstr("x &gt; y"));
}

TEST(SvgFigure, ZeroLengthArrowDrawsNothing) {
  SvgFigure figure;
  figure.circle({0, 0}, 1, {});
  const std::string without = figure.render();
  figure.arrow({1, 1}, {1, 1}, {});
  EXPECT_EQ(figure.render(), without);
}

TEST(SvgFigure, LabelTakesAFreeSpot) {
  // A vertical line through the first spot's place sends the label to the second spot.
  SvgFigure figure;
  figure.line({0, -1}, {0, 1}, {});
  figure.line({0.5, -1}, {0.5, 1}, {});
  figure.label({{{0, 0}, {0, 0}}, {{0, 0}, {-1, 0}}}, "name", "black");
  EXPECT_THAT(figure.render(), HasSubstr("text-anchor=\"end\">name</text>"));
}

TEST(SvgFigure, CoordinatesAcrossTheDoubleRangeStillGiveNumbers) {
  SvgFigure figure;
  figure.circle({-1e308, 0}, 1, {});
  figure.circle({1e308, 0}, 1, {});
  figure.arrow({0, 0}, {std::numeric_limits<double>::infinity(), 0}, {});  // left out
  figure.circle({0, 0}, 5e-324, {});
  const std::string svg = figure.render();
  EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
  EXPECT_EQ(svg.find("inf"), std::string::npos) << svg;
}

}  // namespace
}  // namespace carom::cli
