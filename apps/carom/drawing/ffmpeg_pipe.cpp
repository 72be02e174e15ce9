#include "drawing/ffmpeg_pipe.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace carom::cli {
namespace {

// The last part of ffmpeg's messages that a user needs: its final lines.
constexpr std::size_t kLogTail = 600;

bool is_executable(const std::filesystem::path& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

std::vector<std::string> ffmpeg_arguments(const std::string& ffmpeg, const std::string& path,
                                          VideoFormat format, int width, int height, double fps) {
  std::vector<std::string> args{
      ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
      // Cairo's RGB24 is a native-endian 32-bit 0x00RRGGBB: bytes B, G, R, 0 on x86 and ARM.
      "-f", "rawvideo", "-pix_fmt", "bgr0", "-video_size",
      std::to_string(width) + "x" + std::to_string(height), "-framerate", std::to_string(fps), "-i",
      "pipe:0"};
  if (format == VideoFormat::gif) {
    // One palette for the whole animation, made from every frame, then dithered lightly: the
    // way to a GIF without banding or flicker (ffmpeg's palettegen/paletteuse documentation).
    args.insert(
        args.end(),
        {"-filter_complex",
         "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a",
         "-loop", "0", "-f", "gif"});
  } else {
    // yuv420p and the index at the front (faststart): what browsers play, and start playing
    // before the whole file has arrived.
    args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags",
                             "+faststart", "-f", "mp4"});
  }
  // Bit-exact output: no encoder version or time stamps in the file, so the same frames give
  // the same bytes.
  args.insert(args.end(),
              {"-fflags", "+bitexact", "-flags:v", "+bitexact", "-map_metadata", "-1", path});
  return args;
}

}  // namespace

std::optional<std::string> find_ffmpeg() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::string_view rest(path);
  while (true) {
    const std::size_t colon = rest.find(':');
    const std::string_view dir = rest.substr(0, colon);
    if (!dir.empty()) {
      const std::filesystem::path candidate = std::filesystem::path(dir) / "ffmpeg";
      if (is_executable(candidate)) return candidate.string();
    }
    if (colon == std::string_view::npos) return std::nullopt;
    rest.remove_prefix(colon + 1);
  }
}

FfmpegPipe::FfmpegPipe(const std::string& ffmpeg, const std::string& path, VideoFormat format,
                       int width, int height, double fps)
    : width_(width), height_(height), log_(std::tmpfile()) {
  if (log_ == nullptr) throw std::runtime_error("cannot make a temporary file for ffmpeg's log");
  std::array<int, 2> pipe_ends{-1, -1};
  if (::pipe(pipe_ends.data()) != 0) {
    std::fclose(log_);
    throw std::runtime_error(std::string("cannot make a pipe to ffmpeg: ") + std::strerror(errno));
  }
  // Writing to a pipe ffmpeg has closed must be an error to report, not a signal that kills.
  std::signal(SIGPIPE, SIG_IGN);

  std::vector<std::string> args = ffmpeg_arguments(ffmpeg, path, format, width, height, fps);
  std::vector<char*> argv;
  argv.reserve(args.size() + 1);
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, ::fileno(log_), STDERR_FILENO);
  posix_spawn_file_actions_adddup2(&actions, ::fileno(log_), STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
  // ffmpeg in a process group of its own: Ctrl-C at the terminal reaches carom alone, which then
  // ends the video with the frames it has and lets ffmpeg finish the file.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  const int spawned = posix_spawn(&child_, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_ends[0]);
  if (spawned != 0) {
    ::close(pipe_ends[1]);
    std::fclose(log_);
    child_ = -1;
    throw std::runtime_error("cannot start " + ffmpeg + ": " + std::strerror(spawned));
  }
  input_ = pipe_ends[1];
  // The write end must not leak into other children.
  ::fcntl(input_, F_SETFD, FD_CLOEXEC);
}

FfmpegPipe::~FfmpegPipe() {
  if (input_ >= 0) ::close(input_);
  if (child_ > 0) {
    ::kill(child_, SIGTERM);
    int status = 0;
    while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (log_ != nullptr) std::fclose(log_);
}

std::string FfmpegPipe::failure(const std::string& what) const {
  std::string log;
  std::fflush(log_);
  std::rewind(log_);
  std::array<char, 4096> buffer{};
  std::size_t read = 0;
  while ((read = std::fread(buffer.data(), 1, buffer.size(), log_)) > 0)
    log.append(buffer.data(), read);
  while (!log.empty() && (log.back() == '\n' || log.back() == '\r')) log.pop_back();
  if (log.size() > kLogTail) log = "..." + log.substr(log.size() - kLogTail);
  for (char& c : log) {
    if (c == '\n') c = ' ';  // one message on one line
  }
  return log.empty() ? what : what + ": " + log;
}

void FfmpegPipe::write_frame(const unsigned char* pixels, int stride) {
  const auto row_bytes = static_cast<std::size_t>(width_) * 4;
  for (int row = 0; row < height_; ++row) {
    const unsigned char* data = pixels + static_cast<std::ptrdiff_t>(row) * stride;
    std::size_t left = row_bytes;
    while (left > 0) {
      const ssize_t written = ::write(input_, data, left);
      if (written < 0) {
        if (errno == EINTR) continue;
        throw std::runtime_error(failure("ffmpeg stopped reading frames"));
      }
      data += written;
      left -= static_cast<std::size_t>(written);
    }
  }
}

void FfmpegPipe::finish() {
  ::close(input_);
  input_ = -1;
  int status = 0;
  while (::waitpid(child_, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("lost track of ffmpeg");
  }
  child_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(failure("ffmpeg failed"));
  }
}

}  // namespace carom::cli
