// The SVG builder: fitting, flipping y, and escaping text.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "drawing/svg_writer.hpp"

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

// The canvas's width, from <svg ... width="W" ...>.
double canvas_width(const std::string& svg) {
  const std::size_t value = svg.find("width=\"") + 7;
  return std::stod(svg.substr(value, svg.find('"', value) - value));
}

TEST(SvgFigure, ALongHeadingWrapsInsideTheCanvas) {
  SvgFigure figure;
  figure.circle({0, 0}, 1, {});
  figure.heading("Title");
  std::string words;
  for (int i = 0; i < 40; ++i) words += "word" + std::to_string(i) + " ";
  figure.heading(words);
  const std::string svg = figure.render();
  const double width = canvas_width(svg);
  std::string joined;
  int lines = 0;
  for (std::size_t at = svg.find("<text"); at != std::string::npos;
       at = svg.find("<text", at + 1)) {
    const std::size_t begin = svg.find('>', at) + 1;
    const std::string text = svg.substr(begin, svg.find("</text>", begin) - begin);
    if (text == "Title") continue;
    ++lines;
    joined += text + " ";
    // From the left padding (1.5 font sizes), at 0.6 font sizes a character.
    EXPECT_LE(1.5 * kFontSize + 0.6 * kFontSize * static_cast<double>(text.size()), width);
  }
  EXPECT_GE(lines, 3);
  EXPECT_EQ(joined, words);  // every word, in order
}

TEST(SvgFigure, AViewShowsThatBoxAndClipsToIt) {
  SvgFigure figure;
  figure.view({0, 0}, {4, 2});
  figure.circle({0, 0}, 10, {});  // far larger than the view: fitted to the view, not to it
  const std::string svg = figure.render();
  EXPECT_THAT(svg, HasSubstr("<clipPath id=\"panel0\"><rect x=\""));
  EXPECT_THAT(svg, HasSubstr("width=\"640.00\" height=\"320.00\"/></clipPath>"));
  EXPECT_THAT(svg, HasSubstr("<g class=\"panel\" clip-path=\"url(#panel0)\">"));
  // 4 units across 640 pixels: the circle's radius of 10 is 1600 pixels.
  EXPECT_THAT(svg, HasSubstr("r=\"1600.00\""));
}

TEST(SvgFigure, AnOutlinedArrowLiesOnAWiderBandOfTheOutlineColour) {
  SvgFigure figure;
  figure.arrow({0, 0}, {10, 0}, {"#c00000", 1.0, false}, "#ffffff");
  const std::string svg = figure.render();
  const std::size_t outline = svg.find("stroke=\"#ffffff\" stroke-width=\"6.00\"");
  const std::size_t shaft = svg.find("stroke=\"#c00000\" stroke-width=\"2.00\"");
  ASSERT_NE(outline, std::string::npos);
  ASSERT_NE(shaft, std::string::npos);
  EXPECT_LT(outline, shaft);  // drawn first, so below
  EXPECT_THAT(svg, HasSubstr("fill=\"#ffffff\" stroke=\"#ffffff\" stroke-width=\"4.00\""));
}

}  // namespace
}  // namespace carom::cli
