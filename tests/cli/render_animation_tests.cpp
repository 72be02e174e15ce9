// `carom render SCENE --animate FILE.gif|.mp4`: files browsers play, of the expected size and
// frame count, when ffmpeg is installed; a clear error before any work when it is not.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "drawing/cairo_picture.hpp"
#include "drawing/ffmpeg_pipe.hpp"
#include "drawing/view_box.hpp"
#include "render_scenes.hpp"
#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

// A little-endian 16-bit number at offset.
unsigned le16(const std::string& bytes, std::size_t offset) {
  return static_cast<unsigned char>(bytes[offset]) |
         (static_cast<unsigned>(static_cast<unsigned char>(bytes[offset + 1])) << 8U);
}

TEST(RenderAnimation, GifHasTheFrameSizeAndOneFramePerStep) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  const ToolRun run = run_render({"render", scene, "--animate", (dir / "two.gif").string(),
                                  "--until", "1", "--fps", "10", "--width", "320"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("11 frames"));
  const std::string gif = read_file(dir / "two.gif");
  ASSERT_GE(gif.size(), 13U);
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  EXPECT_EQ(le16(gif, 6), 320U);  // the logical screen's width
  EXPECT_GT(le16(gif, 8), 0U);
  // Each frame carries one graphic control extension (21 F9 04): 0 to 1 s at 10 fps is 11.
  EXPECT_EQ(count_of(gif, std::string("\x21\xf9\x04", 3)), 11);
  EXPECT_FALSE(std::filesystem::exists(dir / "two.gif.tmp"));
}

TEST(RenderAnimation, Mp4IsAnIsoMediaFileWithEvenSides) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  // An odd width is rounded up to even: H.264 in yuv420p needs even sides.
  const ToolRun run =
      run_render({"render", scene, "--animate", (dir / "two.mp4").string(), "--until", "0.5",
                  "--fps", "20", "--width", "321", "--arrows", "--trails", "0.2"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("11 frames, 322x"));
  const std::string mp4 = read_file(dir / "two.mp4");
  ASSERT_GE(mp4.size(), 1000U);
  EXPECT_EQ(mp4.substr(4, 4), "ftyp");
  // faststart: the index (moov) comes before the media data (mdat).
  EXPECT_LT(mp4.find("moov"), mp4.find("mdat"));
}

TEST(RenderAnimation, SameRunGivesTheSameBytes) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  for (const char* name : {"a.gif", "b.gif"}) {
    ASSERT_EQ(run_render({"render", scene, "--animate", (dir / name).string(), "--until", "0.5",
                          "--fps", "10", "--width", "200"})
                  .exit_code,
              0);
  }
  EXPECT_EQ(read_file(dir / "a.gif"), read_file(dir / "b.gif"));
}

// --view frames every frame: the GIF's height is the layout's for that box, not the run's.
TEST(RenderAnimation, ViewSetsTheFramesBox) {
  if (!find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  std::array<int, 2> heights{0, 0};
  for (const char* view : {"0,0,8,2", "0,0,4,4"}) {
    const ToolRun run =
        run_render({"render", scene, "--animate", (dir / "v.gif").string(), "--until", "0.2",
                    "--fps", "10", "--width", "320", "--view", view});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string gif = read_file(dir / "v.gif");
    ASSERT_GE(gif.size(), 13U);
    EXPECT_EQ(le16(gif, 6), 320U);
    heights[view[4] == '8' ? 0 : 1] = static_cast<int>(le16(gif, 8));
  }
  // Balls without colours are drawn by speed, with the legend band below the view.
  EXPECT_EQ(heights[0], layout_image(ViewBox{{0, 0}, {8, 2}}, 320, true, true).height);
  EXPECT_EQ(heights[1], layout_image(ViewBox{{0, 0}, {4, 4}}, 320, true, true).height);
  EXPECT_GT(heights[1], heights[0]);  // a square box is taller than a wide one
}

// PATH pointing at another folder (an empty one, or one with a stand-in) for one run.
class PathWithoutFfmpeg {
 public:
  explicit PathWithoutFfmpeg(const std::filesystem::path& empty_dir) {
    if (const char* path = std::getenv("PATH")) saved_ = path;
    ::setenv("PATH", empty_dir.c_str(), 1);
  }
  ~PathWithoutFfmpeg() {
    if (saved_) {
      ::setenv("PATH", saved_->c_str(), 1);
    } else {
      ::unsetenv("PATH");
    }
  }
  PathWithoutFfmpeg(const PathWithoutFfmpeg&) = delete;
  PathWithoutFfmpeg& operator=(const PathWithoutFfmpeg&) = delete;

 private:
  std::optional<std::string> saved_;
};

TEST(RenderAnimation, MissingFfmpegIsAUsageErrorBeforeAnyWork) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  std::filesystem::create_directory(dir / "empty");
  ToolRun run;
  {
    const PathWithoutFfmpeg hidden(dir / "empty");
    run = run_render({"render", scene, "--animate", (dir / "two.gif").string(), "--until", "1"});
  }
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(count_of(run.err, "\n"), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("--animate"));
  EXPECT_THAT(run.err, HasSubstr("ffmpeg"));
  EXPECT_FALSE(std::filesystem::exists(dir / "two.gif"));
  EXPECT_FALSE(std::filesystem::exists(dir / "two.gif.tmp"));
}

TEST(RenderAnimation, FfmpegFailingIsReportedWithItsMessageAndLeavesNoFile) {
  const ScratchDir dir;
  const std::string scene = write_test_scene(dir, "two.json", kTwoBallsScene);
  // A stand-in ffmpeg that refuses at once, as a real one does when an encoder is missing.
  std::filesystem::create_directory(dir / "bin");
  write_test_scene(dir, "bin/ffmpeg", "#!/bin/sh\necho 'Unknown encoder libx264' >&2\nexit 1\n");
  std::filesystem::permissions(dir / "bin" / "ffmpeg", std::filesystem::perms::owner_all);
  ToolRun run;
  {
    const PathWithoutFfmpeg stand_in(dir / "bin");
    run = run_render({"render", scene, "--animate", (dir / "two.mp4").string(), "--until", "1"});
  }
  EXPECT_EQ(run.exit_code, 1);  // not the caller's input: the tool it relies on failed
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(count_of(run.err, "\n"), 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("ffmpeg"));
  EXPECT_THAT(run.err, HasSubstr("Unknown encoder libx264"));
  EXPECT_FALSE(std::filesystem::exists(dir / "two.mp4"));
  EXPECT_FALSE(std::filesystem::exists(dir / "two.mp4.tmp"));
}

}  // namespace
}  // namespace carom::cli::test
