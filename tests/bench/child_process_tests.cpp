// carom_bench_goals' process runner: what the program wrote comes back whole, its failures are
// errors that say which, and a stop signal sent to this process reaches the program too.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <stdexcept>
#include <string>

#include "child_process.hpp"

namespace carom::goals::test {
namespace {

using ::testing::HasSubstr;

TEST(ChildProcess, ReturnsWhatTheProgramWroteHoweverLong) {
  EXPECT_EQ(output_of_program("/bin/sh", {"-c", "printf 'measured %s' \"$0\"", "gas"}),
            "measured gas");
  // More than a pipe holds at once (64 KiB on Linux): the parent reads while the child writes.
  const std::string out =
      output_of_program("/bin/sh", {"-c",
                                    "i=0; while [ $i -lt 3000 ]; do printf '%0100d' $i; "
                                    "i=$((i + 1)); done"});
  ASSERT_EQ(out.size(), 300'000U);
  EXPECT_EQ(out.substr(out.size() - 4), "2999");
}

TEST(ChildProcess, AFailingOrKilledOrMissingProgramIsAnError) {
  EXPECT_THAT(
      [] {
        (void)output_of_program("/bin/sh", {"-c", "exit 3"});
      },
      ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("exit status 3")));
  EXPECT_THAT(
      [] {
        (void)output_of_program("/bin/sh", {"-c", "kill -9 $$"});
      },
      ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("signal 9")));
  EXPECT_THAT([] { (void)output_of_program("/nonexistent/carom", {}); },
              ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("exit status 127")));
}

TEST(ChildProcess, AStopSignalToThisProcessIsRecordedAndPassedOnToTheProgram) {
  const StopSignals stop_signals;
  EXPECT_EQ(StopSignals::received(), 0);
  // The program signals its parent, this process, then waits: only the signal passed on ends it
  // (before its 20 seconds are up), and it is killed by that very signal.
  EXPECT_THAT(
      [] {
        (void)output_of_program("/bin/sh", {"-c", "kill -TERM $PPID; exec sleep 20"});
      },
      ::testing::ThrowsMessage<std::runtime_error>(HasSubstr("killed by signal 15")));
  EXPECT_EQ(StopSignals::received(), SIGTERM);
  EXPECT_EQ(StopSignals::what(), "terminated (SIGTERM)");
}

}  // namespace
}  // namespace carom::goals::test
