// Where label text goes and what it covers.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drawing/label_placement.hpp"

namespace carom::cli {
namespace {

const TextBox kBox{{0, 0}, {10, 5}};

TEST(Obstacles, SegmentsCountWhenTheyCrossOrLieInTheBox) {
  Obstacles crossing;
  crossing.add_segment({-5, 2}, {15, 3});
  EXPECT_EQ(crossing.collisions(kBox), 1);

  Obstacles inside;
  inside.add_segment({2, 2}, {3, 3});
  EXPECT_EQ(inside.collisions(kBox), 1);

  Obstacles beside;
  beside.add_segment({-5, -1}, {15, -1});  // parallel, just above
  beside.add_segment({11, -10}, {20, 10});
  EXPECT_EQ(beside.collisions(kBox), 0);
}

TEST(Obstacles, OnlyACirclesOutlineCounts) {
  Obstacles around;
  around.add_circle({5, 2.5}, 100);  // the box lies inside: free
  EXPECT_EQ(around.collisions(kBox), 0);

  Obstacles through;
  through.add_circle({0, 0}, 3);
  EXPECT_EQ(through.collisions(kBox), 1);

  Obstacles away;
  away.add_circle({50, 50}, 3);
  EXPECT_EQ(away.collisions(kBox), 0);
}

TEST(Obstacles, EarlierLabelsCount) {
  Obstacles labels;
  labels.add_box({{9, 4}, {20, 8}});
  EXPECT_EQ(labels.collisions(kBox), 1);
}

TEST(PlaceText, SitsOnTheSideItIsSentTo) {
  const PlacedText right = place_text({100, 100}, {1, 0}, "va");
  EXPECT_EQ(right.anchor, TextAnchor::kStart);
  EXPECT_GT(right.box.min.x, 100.0);

  const PlacedText left = place_text({100, 100}, {-1, 0}, "va");
  EXPECT_EQ(left.anchor, TextAnchor::kEnd);
  EXPECT_LT(left.box.max.x, 100.0);

  const PlacedText above = place_text({100, 100}, {0, -1}, "va");  // screen y points down
  EXPECT_EQ(above.anchor, TextAnchor::kMiddle);
  EXPECT_LT(above.box.max.y, 100.0);
}

TEST(CountCharacters, CountsLettersNotBytes) {
  EXPECT_EQ(count_characters("va′"), 3u);
  EXPECT_EQ(count_characters("va − vb"), 7u);
}

TEST(WrapWords, BreaksAtSpacesWithinTheWidth) {
  using Lines = std::vector<std::string>;
  EXPECT_EQ(wrap_words("one two three four", 9), (Lines{"one two", "three", "four"}));
  EXPECT_EQ(wrap_words("one two three four", 100), (Lines{"one two three four"}));
  // A word longer than the width keeps a line of its own; extra spaces are dropped.
  EXPECT_EQ(wrap_words("a  verylongword b", 4), (Lines{"a", "verylongword", "b"}));
  EXPECT_EQ(wrap_words("", 10), Lines{});
  // Characters, not bytes: "p′ − q" is six characters.
  EXPECT_EQ(wrap_words("p′ − q r", 6), (Lines{"p′ − q", "r"}));
}

TEST(WrapWords, CharactersInAWidth) {
  EXPECT_EQ(characters_in(60.0, 10.0, false), 10U);  // 0.6 font sizes a character
  EXPECT_EQ(characters_in(65.0, 10.0, true), 10U);   // 0.65 in bold
  EXPECT_EQ(characters_in(1.0, 10.0, false), 1U);    // always at least one
}

}  // namespace
}  // namespace carom::cli
