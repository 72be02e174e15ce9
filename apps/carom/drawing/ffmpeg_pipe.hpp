// carom tool: encoding animation frames with the ffmpeg program (Debian package ffmpeg).
//
// Frames go to ffmpeg's standard input as raw video (Cairo's RGB24 pixels, which ffmpeg calls
// bgr0 on a little-endian machine); ffmpeg writes the file. An animated GIF goes through
// ffmpeg's palettegen / paletteuse filters (a palette made for these frames, not a fixed one);
// an MP4 is H.264 in yuv420p with the index at the front, the form every browser plays.
#pragma once

#include <sys/types.h>

#include <cstdio>
#include <optional>
#include <string>

namespace carom::cli {

enum class VideoFormat { gif, mp4 };

// The ffmpeg program on PATH, or nothing when there is none.
[[nodiscard]] std::optional<std::string> find_ffmpeg();

class FfmpegPipe {
 public:
  // Starts ffmpeg writing `format` to path, reading frames of width × height at fps.
  // Throws std::runtime_error when ffmpeg cannot be started.
  FfmpegPipe(const std::string& ffmpeg, const std::string& path, VideoFormat format, int width,
             int height, double fps);
  // Stops ffmpeg if finish() was not called (the file it wrote is then incomplete; the caller
  // removes it).
  ~FfmpegPipe();
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  // One frame: height rows of width × 4 bytes, stride bytes apart. Throws std::runtime_error
  // (with ffmpeg's own message) when ffmpeg stopped reading.
  void write_frame(const unsigned char* pixels, int stride);
  // Closes the input and waits for ffmpeg; throws std::runtime_error if it failed.
  void finish();

 private:
  [[nodiscard]] std::string failure(const std::string& what) const;

  int width_;
  int height_;
  int input_ = -1;            // the write end of ffmpeg's standard input
  std::FILE* log_ = nullptr;  // ffmpeg's standard error (an anonymous temporary file)
  pid_t child_ = -1;
};

}  // namespace carom::cli
