// What an output name stands for is kept: a symbolic link stays a link and its target is written,
// a FIFO's reader gets the output, a device stays a device, "-" is standard output (and as SCENE,
// standard input), and a folder, a disk or two names for one file are refused before the run.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "options/exit_codes.hpp"
#include "run_tool.hpp"
#include "scene_files.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The cradle's contacts to t = 10, as JSON lines: the content every test below expects.
std::vector<std::string> cradle_events(const ScratchDir& dir) {
  const std::string plain = (dir / "plain.jsonl").string();
  const ToolRun run = run_carom(
      {"run", example("newtons-cradle.json"), "--until", "10", "--events", plain, "--quiet"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const std::vector<std::string> lines = lines_of(read_file(plain));
  EXPECT_GT(lines.size(), 3U);
  return lines;
}

// Reads a FIFO (or a socket's connection) to its end on another thread.
std::future<std::string> read_all(int fd) {
  return std::async(std::launch::async, [fd] {
    std::string text;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      text.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return text;
  });
}

TEST(OutputTarget, ASymbolicLinkStaysALinkAndItsTargetIsWritten) {
  const ScratchDir dir;
  const std::vector<std::string> expected = cradle_events(dir);
  std::filesystem::create_directory(dir / "data");
  const auto target = dir / "data" / "events.jsonl";
  std::ofstream(target) << "old\n";
  const auto link = dir / "events-link";
  std::filesystem::create_symlink("data/events.jsonl", link);  // relative, as users make them
  // A link to a missing file is written too (its target created), the link kept.
  const auto dangling = dir / "dangling-link";
  std::filesystem::create_symlink(dir / "data" / "new.csv", dangling);

  const ToolRun run =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--events", link.string(),
                 "--frames", dangling.string(), "--format", "csv", "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_TRUE(std::filesystem::is_symlink(dangling));
  EXPECT_EQ(lines_of(read_file(target)), expected);
  EXPECT_THAT(read_file(dir / "data" / "new.csv"), HasSubstr("time,index,name,x,y,vx,vy,radius"));
  EXPECT_FALSE(std::filesystem::exists(dir / "data" / "events.jsonl.tmp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "events-link.tmp"));
}

TEST(OutputTarget, AFifosReaderGetsTheWholeOutputAndTheFifoStays) {
  const ScratchDir dir;
  const std::vector<std::string> expected = cradle_events(dir);
  const auto fifo = dir / "events.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  // The reader opens its end on its own thread (open blocks until the tool opens the other).
  std::future<std::string> got = std::async(std::launch::async, [&fifo] {
    const int fd = ::open(fifo.c_str(), O_RDONLY);
    return fd < 0 ? std::string("cannot open") : read_all(fd).get();
  });
  const ToolRun run = run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--events",
                                 fifo.string(), "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(lines_of(got.get()), expected);
  struct stat status {};
  ASSERT_EQ(::lstat(fifo.c_str(), &status), 0);
  EXPECT_TRUE(S_ISFIFO(status.st_mode));
}

TEST(OutputTarget, AUnixSocketIsConnectedToAndWritten) {
  const ScratchDir dir;
  const std::vector<std::string> expected = cradle_events(dir);
  const auto path = dir / "events.sock";
  const int listener = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(listener, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.string().size(), sizeof address.sun_path);
  std::strcpy(address.sun_path, path.c_str());
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API's own cast.
  ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(listener, 1), 0);
  std::future<std::string> got = std::async(std::launch::async, [listener] {
    const int connection = ::accept(listener, nullptr, nullptr);
    ::close(listener);
    return connection < 0 ? std::string("cannot accept") : read_all(connection).get();
  });
  const ToolRun run = run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--events",
                                 path.string(), "--quiet"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(lines_of(got.get()), expected);
}

// As root (CI), a character device made with mknod: /dev/null's numbers in a scratch folder.
TEST(OutputTarget, ACharacterDeviceStaysADevice) {
  const ScratchDir dir;
  const auto device = dir / "null";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) {
    GTEST_SKIP() << "mknod needs root: " << std::strerror(errno);
  }
  const ToolRun run = run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--events",
                                 device.string(), "--frames", device.string(), "--format", "xyz",
                                 "--save", device.string(), "--stats"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  struct stat status {};
  ASSERT_EQ(::lstat(device.c_str(), &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
  EXPECT_FALSE(std::filesystem::exists(dir / "null.tmp"));
}

TEST(OutputTarget, DevNullIsWrittenAndKept) {
  const ToolRun run = run_carom(
      {"run", example("newtons-cradle.json"), "--until", "10", "--events", "/dev/null", "--quiet"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  struct stat status {};
  ASSERT_EQ(::lstat("/dev/null", &status), 0);
  EXPECT_TRUE(S_ISCHR(status.st_mode));
}

// As root, a block device is refused before anything is written to it.
TEST(OutputTarget, ABlockDeviceIsRefused) {
  const ScratchDir dir;
  const auto disk = dir / "disk";
  if (::mknod(disk.c_str(), S_IFBLK | 0600, makedev(7, 255)) != 0) {
    GTEST_SKIP() << "mknod needs root: " << std::strerror(errno);
  }
  const ToolRun run = run_carom(
      {"run", example("newtons-cradle.json"), "--until", "10", "--events", disk.string()});
  EXPECT_EQ(run.exit_code, kExitUsage);
  EXPECT_THAT(run.err, HasSubstr("block device"));
}

TEST(OutputTarget, DashIsStandardOutputAndTheSummaryMovesToStderr) {
  const ScratchDir dir;
  const std::vector<std::string> expected = cradle_events(dir);
  const ToolRun events = run_carom(
      {"run", example("newtons-cradle.json"), "--until", "10", "--events", "-", "--stats"});
  ASSERT_EQ(events.exit_code, 0) << events.err;
  EXPECT_EQ(lines_of(events.out), expected);
  EXPECT_THAT(events.err, HasSubstr("collisions"));

  const ToolRun frames = run_carom({"run", example("newtons-cradle.json"), "--until", "10",
                                    "--frames", "-", "--format", "xyz", "--every", "5"});
  ASSERT_EQ(frames.exit_code, 0) << frames.err;
  const std::vector<std::string> rows = lines_of(frames.out);
  ASSERT_FALSE(rows.empty());
  const std::size_t balls = std::stoul(rows.front());
  EXPECT_EQ(rows.size(), 3 * (balls + 2));  // frames at 0, 5 and 10
  EXPECT_THAT(frames.err, HasSubstr("ran "));

  const ToolRun both = run_carom({"run", example("newtons-cradle.json"), "--until", "10",
                                  "--frames", "-", "--format", "csv", "--events", "-"});
  EXPECT_EQ(both.exit_code, kExitUsage);
  EXPECT_THAT(both.err, HasSubstr("the same file as --frames"));
  const ToolRun no_format =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--frames", "-"});
  EXPECT_EQ(no_format.exit_code, kExitUsage);
  EXPECT_THAT(no_format.err, HasSubstr("--format csv|xyz"));
}

TEST(OutputTarget, DashAsTheSceneReadsStandardInput) {
  const std::string scene = read_file(example("newtons-cradle.json"));
  const ToolRun run = run_carom({"run", "-", "--until", "10", "--stats", "--json"}, scene);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto stats = nlohmann::json::parse(run.out);
  EXPECT_EQ(stats["scene"], "<stdin>");
  EXPECT_GT(stats["collisions"].get<int>(), 0);
  const ToolRun info = run_carom({"info", "-"}, scene);
  EXPECT_EQ(info.exit_code, 0) << info.err;
  // An error in a scene from standard input names it so, with the line.
  const ToolRun bad = run_carom({"run", "-", "--until", "10"}, std::string("{\n  \"balls\": 3\n}"));
  EXPECT_EQ(bad.exit_code, kExitUsage);
  EXPECT_THAT(bad.err, HasSubstr("<stdin>:2"));
}

TEST(OutputTarget, AFolderIsRefusedAsAnOutputAndAsAScene) {
  const ScratchDir dir;
  const ToolRun output = run_carom(
      {"run", example("newtons-cradle.json"), "--until", "10", "--events", dir.path().string()});
  EXPECT_EQ(output.exit_code, kExitUsage);
  EXPECT_THAT(output.err, HasSubstr("is a folder"));
  const ToolRun scene = run_carom({"run", dir.path().string(), "--until", "10"});
  EXPECT_EQ(scene.exit_code, kExitUsage);
  EXPECT_THAT(scene.err, HasSubstr("is a folder, not a scene file"));
  EXPECT_THAT(scene.err, Not(HasSubstr("JSON")));
}

TEST(OutputTarget, TwoNamesForOneFileAreRefused) {
  const ScratchDir dir;
  const auto file = dir / "out.csv";
  std::filesystem::create_symlink(file, dir / "alias.csv");
  const ToolRun run = run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--frames",
                                 file.string(), "--events", (dir / "alias.csv").string()});
  EXPECT_EQ(run.exit_code, kExitUsage);
  EXPECT_THAT(run.err, HasSubstr("the same file as --frames"));
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(OutputTarget, ErrorsNameTheFileTheUserGave) {
  const ScratchDir dir;
  const std::string missing = (dir / "no-such-folder" / "events.jsonl").string();
  const ToolRun run =
      run_carom({"run", example("newtons-cradle.json"), "--until", "10", "--events", missing});
  EXPECT_EQ(run.exit_code, kExitUsage);
  EXPECT_THAT(run.err, HasSubstr("--events \"" + missing + "\""));
  EXPECT_THAT(run.err, HasSubstr("does not exist"));
}

TEST(OutputTarget, AnOutputLargerThanTheFreeSpaceIsRefusedBeforeTheRun) {
  const ScratchDir dir;
  const std::string frames = (dir / "huge.csv").string();
  // 10¹² frames of the box of 1000: far beyond any disk.
  const ToolRun run = run_carom({"run", example("box-of-1000.json"), "--until", "1e9", "--every",
                                 "1e-3", "--frames", frames});
  EXPECT_EQ(run.exit_code, kExitUsage);
  EXPECT_THAT(run.err, HasSubstr("refused before the run"));
  EXPECT_THAT(run.err, HasSubstr("would take about"));
  EXPECT_FALSE(std::filesystem::exists(frames));
  EXPECT_FALSE(std::filesystem::exists(frames + ".tmp"));
}

}  // namespace
}  // namespace carom::cli::test
