// AtomicFile: a file replaced holds its old content or all of the new one; no temporary file is
// left behind, whether the writer commits, fails or gives up; links stay links.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "carom/atomic_file.hpp"

namespace {

// fsync as the C library's, counting the calls on plain files and on folders while asked to.
std::atomic<bool> g_count_syncs{false};
std::atomic<int> g_file_syncs{0};
std::atomic<int> g_folder_syncs{0};

}  // namespace

// Takes the place of the C library's fsync in this test program (the library is linked in
// statically), so that a test can see which syncs a commit asks for.
extern "C" int fsync(int fd) {
  if (g_count_syncs.load()) {
    struct stat status {};
    if (::fstat(fd, &status) == 0) {
      if (S_ISDIR(status.st_mode)) ++g_folder_syncs;
      if (S_ISREG(status.st_mode)) ++g_file_syncs;
    }
  }
  return static_cast<int>(::syscall(SYS_fsync, fd));
}

namespace carom {
namespace {

namespace fs = std::filesystem;

// A fresh folder of its own for each test, removed after it.
class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("carom_atomic_file_" + std::string(test->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(dir_, ignored);
  }

  [[nodiscard]] const fs::path& dir() const { return dir_; }

  // The names in a folder (the test's own by default), sorted.
  [[nodiscard]] std::vector<std::string> names(const fs::path& folder = {}) const {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(folder.empty() ? dir_ : folder)) {
      found.push_back(entry.path().filename().string());
    }
    std::sort(found.begin(), found.end());
    return found;
  }

 private:
  fs::path dir_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// What call throws as a FileError, checked to be one; "" when it throws nothing.
std::string file_error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const FileError& error) {
    return error.what();
  }
  return "";
}

TEST_F(AtomicFileTest, WritesANewFileAndReplacesItWhole) {
  const fs::path path = dir() / "out.txt";
  write_file_atomically(path, "first\n");
  EXPECT_EQ(read_text(path), "first\n");
  {
    AtomicFile file(path);
    file.write("second,");
    file.write(" in two parts\n");
    // Until the commit the old content stands, and the new one is in the temporary beside it.
    EXPECT_EQ(read_text(path), "first\n");
    EXPECT_EQ(file.temporary().parent_path(), dir());
    EXPECT_EQ(read_text(file.temporary()), "second, in two parts\n");
    file.commit();
    EXPECT_TRUE(file.temporary().empty());
  }
  EXPECT_EQ(read_text(path), "second, in two parts\n");
  EXPECT_EQ(names(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, TemporaryNamesAreUniqueOrFixed) {
  const fs::path path = dir() / "world.save";
  AtomicFile first(path);
  AtomicFile second(path);
  const std::regex unique(R"(world\.save\.[A-Za-z0-9]{6})");
  EXPECT_TRUE(std::regex_match(first.temporary().filename().string(), unique)) << first.temporary();
  EXPECT_NE(first.temporary(), second.temporary());
  // Two writers of one file at once: each renames a whole file of its own; the last one wins.
  first.write("from the first writer");
  second.write("from the second writer");
  first.commit();
  second.commit();
  EXPECT_EQ(read_text(path), "from the second writer");
  EXPECT_EQ(names(), std::vector<std::string>{"world.save"});

  // A fixed name is TARGET.tmp, and one left by a killed writer is overwritten.
  write_text(dir() / "world.save.tmp", "a killed writer's half-written content, longer");
  AtomicFile fixed(path, {.temporary = TemporaryName::fixed});
  EXPECT_EQ(fixed.temporary(), dir() / "world.save.tmp");
  fixed.write("fixed");
  fixed.commit();
  EXPECT_EQ(read_text(path), "fixed");
  EXPECT_EQ(names(), std::vector<std::string>{"world.save"});
}

TEST_F(AtomicFileTest, UncommittedTheTemporaryIsRemovedAndTheFileKept) {
  const fs::path path = dir() / "kept.txt";
  write_text(path, "old");
  for (const TemporaryName naming : {TemporaryName::unique, TemporaryName::fixed}) {
    fs::path temporary;
    {
      AtomicFile file(path, {.temporary = naming});
      file.write("new, never committed");
      temporary = file.temporary();
      EXPECT_TRUE(fs::exists(temporary));
    }
    EXPECT_FALSE(fs::exists(temporary));
    EXPECT_EQ(read_text(path), "old");
    EXPECT_EQ(names(), std::vector<std::string>{"kept.txt"});
  }
  // Moved, the temporary belongs to the new owner: the moved-from one neither removes nor commits.
  std::optional<AtomicFile> moved;
  {
    AtomicFile file(path);
    file.write("moved");
    moved.emplace(std::move(file));
  }
  EXPECT_TRUE(fs::exists(moved->temporary()));
  moved->commit();
  EXPECT_EQ(read_text(path), "moved");
  EXPECT_EQ(names(), std::vector<std::string>{"kept.txt"});
}

TEST_F(AtomicFileTest, AFailedWriteRemovesTheTemporaryAndKeepsTheFile) {
  const fs::path path = dir() / "big.bin";
  write_text(path, "old");
  // A file-size limit makes write() fail (EFBIG, with SIGXFSZ ignored), as a full disk would.
  rlimit before{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &before), 0);
  const rlimit small{1024, before.rlim_max};
  auto* const old_handler = std::signal(SIGXFSZ, SIG_IGN);
  AtomicFile file(path);
  const fs::path temporary = file.temporary();
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string what = file_error_of([&] { file.write(std::string(4096, 'x')); });
  ::setrlimit(RLIMIT_FSIZE, &before);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(what.find(path.string() + ": cannot write its temporary file " + temporary.string()),
            std::string::npos)
      << what;
  EXPECT_NE(what.find(std::strerror(EFBIG)), std::string::npos) << what;
  EXPECT_TRUE(file.temporary().empty());
  EXPECT_EQ(names(), std::vector<std::string>{"big.bin"});
  EXPECT_EQ(read_text(path), "old");
  // A failed file takes nothing more.
  EXPECT_NE(file_error_of([&] { file.write("more"); }).find("not open"), std::string::npos);
  EXPECT_NE(file_error_of([&] { file.commit(); }).find("not open"), std::string::npos);
  EXPECT_EQ(read_text(path), "old");
}

TEST_F(AtomicFileTest, AFailedRenameRemovesTheTemporary) {
  const fs::path path = dir() / "becomes-a-folder";
  AtomicFile file(path);
  file.write("content");
  // The target turned into a folder (with a file in it) between the open and the commit.
  fs::create_directory(path);
  write_text(path / "inside", "");
  const std::string what = file_error_of([&] { file.commit(); });
  EXPECT_NE(what.find(path.string() + ": cannot rename its temporary file "), std::string::npos)
      << what;
  EXPECT_NE(what.find(" onto it: "), std::string::npos) << what;
  EXPECT_EQ(names(), std::vector<std::string>{"becomes-a-folder"});
  EXPECT_EQ(names(path), std::vector<std::string>{"inside"});
}

TEST_F(AtomicFileTest, ThroughSymbolicLinksTheTargetIsReplacedAndTheLinksKept) {
  fs::create_directories(dir() / "data");
  fs::create_directories(dir() / "links");
  write_text(dir() / "data" / "real.csv", "old");
  // A relative link is read from its own folder: links/near -> ../data/real.csv; far -> near.
  fs::create_symlink(fs::path("..") / "data" / "real.csv", dir() / "links" / "near");
  fs::create_symlink(dir() / "links" / "near", dir() / "far");
  for (const TemporaryName naming : {TemporaryName::unique, TemporaryName::fixed}) {
    AtomicFile file(dir() / "far", {.temporary = naming});
    EXPECT_EQ(file.target(), dir() / "links" / ".." / "data" / "real.csv");
    EXPECT_EQ(file.temporary().parent_path(), file.target().parent_path());
    file.write(naming == TemporaryName::unique ? "unique" : "fixed");
    file.commit();
    EXPECT_TRUE(fs::is_symlink(dir() / "far"));
    EXPECT_TRUE(fs::is_symlink(dir() / "links" / "near"));
    EXPECT_EQ(read_text(dir() / "far"), naming == TemporaryName::unique ? "unique" : "fixed");
    EXPECT_EQ(names(dir() / "data"), std::vector<std::string>{"real.csv"});
    EXPECT_EQ(names(dir() / "links"), std::vector<std::string>{"near"});
  }
  // A link to a file not there yet makes the file, and stays a link.
  fs::create_symlink("later.csv", dir() / "dangling");
  write_file_atomically(dir() / "dangling", "made");
  EXPECT_TRUE(fs::is_symlink(dir() / "dangling"));
  EXPECT_EQ(read_text(dir() / "later.csv"), "made");
}

TEST_F(AtomicFileTest, FollowLinksStopsAtLoopsAndMissingFiles) {
  std::error_code error;
  EXPECT_EQ(follow_links(dir() / "missing", error), dir() / "missing");
  EXPECT_FALSE(error);
  fs::create_symlink("b", dir() / "a");
  fs::create_symlink("a", dir() / "b");
  (void)follow_links(dir() / "a", error);
  EXPECT_EQ(error, std::error_code(ELOOP, std::generic_category()));
  const std::string what = file_error_of([&] { AtomicFile file(dir() / "a"); });
  EXPECT_NE(what.find(dir().string() + "/a: cannot follow its links: "), std::string::npos) << what;
  // Through a file as if it were a folder: not missing, not followable.
  write_text(dir() / "file", "");
  (void)follow_links(dir() / "file" / "x", error);
  EXPECT_EQ(error, std::error_code(ENOTDIR, std::generic_category()));
}

TEST_F(AtomicFileTest, ATargetThatIsNoPlainFileIsRefusedUntouched) {
  fs::create_directory(dir() / "folder");
  EXPECT_EQ(file_error_of([&] { AtomicFile file(dir() / "folder"); }),
            (dir() / "folder").string() + ": is a folder");
  ASSERT_EQ(::mkfifo((dir() / "fifo").c_str(), 0600), 0) << std::strerror(errno);
  const std::string fifo = file_error_of([&] { write_file_atomically(dir() / "fifo", "x"); });
  EXPECT_NE(fifo.find("fifo: is not a plain file"), std::string::npos) << fifo;
  EXPECT_TRUE(fs::is_fifo(dir() / "fifo"));
  EXPECT_EQ(file_error_of([&] { AtomicFile file(""); }), ": the file name is empty");
  EXPECT_EQ(names(), (std::vector<std::string>{"fifo", "folder"}));
}

// What creating an AtomicFile at path throws, tried as a user without privileges: as root, in a
// child process that becomes the user "nobody" (root may write into any folder).
std::string error_without_privileges(const fs::path& path) {
  if (::geteuid() != 0) return file_error_of([&] { AtomicFile file(path); });
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return "no pipe";
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    constexpr uid_t kNobody = 65534;
    std::string what = "cannot become nobody";
    if (::setgid(kNobody) == 0 && ::setuid(kNobody) == 0) {
      what = file_error_of([&] { AtomicFile file(path); });
    }
    if (::write(pipe_fds[1], what.data(), what.size()) < 0) ::_exit(1);
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  std::string what;
  char buffer[256];
  ssize_t n = 0;
  while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0) {
    what.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  return what;
}

TEST_F(AtomicFileTest, AFolderThatRefusesIsNamedInTheError) {
  const fs::path missing = dir() / "missing" / "out.txt";
  const std::string absent = file_error_of([&] { write_file_atomically(missing, "x"); });
  EXPECT_NE(absent.find(missing.string() + ": cannot create its temporary file " +
                        missing.string() + "."),
            std::string::npos)
      << absent;
  EXPECT_NE(absent.find(std::strerror(ENOENT)), std::string::npos) << absent;

  const fs::path locked = dir() / "locked";
  fs::create_directory(locked);
  write_text(locked / "out.txt", "old");
  fs::permissions(dir(), fs::perms::others_exec, fs::perm_options::add);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  const std::string refused = error_without_privileges(locked / "out.txt");
  EXPECT_NE(refused.find((locked / "out.txt").string() + ": cannot create its temporary file "),
            std::string::npos)
      << refused;
  EXPECT_NE(refused.find(std::strerror(EACCES)), std::string::npos) << refused;
  EXPECT_EQ(read_text(locked / "out.txt"), "old");
  EXPECT_EQ(names(locked), std::vector<std::string>{"out.txt"});
  fs::permissions(locked, fs::perms::owner_all, fs::perm_options::add);
}

TEST_F(AtomicFileTest, SyncFlushesTheFileBeforeTheRenameAndTheFolderAfter) {
  const fs::path path = dir() / "synced";
  g_file_syncs = 0;
  g_folder_syncs = 0;
  g_count_syncs = true;
  write_file_atomically(path, "synced");
  const int synced_files = g_file_syncs.exchange(0);
  const int synced_folders = g_folder_syncs.exchange(0);
  write_file_atomically(path, "not synced", {.sync = false});
  const int unsynced_files = g_file_syncs.exchange(0);
  const int unsynced_folders = g_folder_syncs.exchange(0);
  g_count_syncs = false;
  EXPECT_EQ(synced_files, 1);
  EXPECT_EQ(synced_folders, 1);
  EXPECT_EQ(unsynced_files, 0);
  EXPECT_EQ(unsynced_folders, 0);
  EXPECT_EQ(read_text(path), "not synced");
}

TEST_F(AtomicFileTest, KeepPreviousRotatesTheFileReplacedToPrev) {
  const fs::path path = dir() / "run.ckpt";
  const AtomicFileOptions options{.temporary = TemporaryName::fixed, .keep_previous = true};
  write_file_atomically(path, "first", options);
  EXPECT_EQ(names(), std::vector<std::string>{"run.ckpt"});
  write_file_atomically(path, "second", options);
  write_file_atomically(path, "third", options);
  EXPECT_EQ(read_text(path), "third");
  EXPECT_EQ(read_text(dir() / "run.ckpt.prev"), "second");
  EXPECT_EQ(names(), (std::vector<std::string>{"run.ckpt", "run.ckpt.prev"}));

  // A .prev that cannot be replaced (a folder with a file in it): the file stays as it was.
  fs::remove(dir() / "run.ckpt.prev");
  fs::create_directory(dir() / "run.ckpt.prev");
  write_text(dir() / "run.ckpt.prev" / "inside", "");
  const std::string what = file_error_of([&] { write_file_atomically(path, "fourth", options); });
  EXPECT_NE(what.find(path.string() + ": cannot rename " + path.string() + " to " + path.string() +
                      ".prev: "),
            std::string::npos)
      << what;
  EXPECT_EQ(read_text(path), "third");
  EXPECT_EQ(names(), (std::vector<std::string>{"run.ckpt", "run.ckpt.prev"}));
}

TEST_F(AtomicFileTest, PermissionsOfAReplacedFileAreKept) {
  const fs::path path = dir() / "private";
  write_text(path, "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  write_file_atomically(path, "new");
  EXPECT_EQ(fs::status(path).permissions(), fs::perms::owner_read | fs::perms::owner_write);
  // A new file gets what any new file gets: 0666 less the umask.
  const mode_t umask_before = ::umask(022);
  write_file_atomically(dir() / "fresh", "new");
  ::umask(umask_before);
  EXPECT_EQ(fs::status(dir() / "fresh").permissions(),
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                fs::perms::others_read);
}

}  // namespace
}  // namespace carom
