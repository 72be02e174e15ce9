// `carom sweep` with bad input: one message on stderr naming the option and the value, exit
// status 2, nothing on stdout, never a crash.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>

#include "run_tool.hpp"

namespace carom::cli::test {
namespace {

using ::testing::HasSubstr;

struct BadInput {
  std::string name;                        // the test's name
  std::vector<std::string> changes;        // options replacing or added to the good case
  std::vector<std::string> message_parts;  // what the message must contain
};

void PrintTo(const BadInput& input, std::ostream* os) { *os << input.name; }

// The good case with each "--option value" pair of changes put in; a change whose value is
// "<drop>" removes the option instead.
std::vector<std::string> with_changes(const std::vector<std::string>& changes) {
  std::vector<std::string> args{"sweep", "--a",     "0,0,1", "--va", "6,2",
                                "--b",   "8,3,1.5", "--vb",  "-4,-1"};
  for (std::size_t i = 0; i + 1 < changes.size(); i += 2) {
    const auto found = std::find(args.begin(), args.end(), changes[i]);
    if (changes[i + 1] == "<drop>") {
      if (found != args.end()) args.erase(found, found + 2);
    } else if (found != args.end()) {
      *(found + 1) = changes[i + 1];
    } else {
      args.push_back(changes[i]);
      args.push_back(changes[i + 1]);
    }
  }
  if (changes.size() % 2 == 1) args.push_back(changes.back());  // a lone extra word
  return args;
}

class SweepBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SweepBadInput, OneMessageNamingOptionAndValueAndStatusTwo) {
  const ToolRun run = run_carom(with_changes(GetParam().changes));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  for (const std::string& part : GetParam().message_parts) {
    EXPECT_THAT(run.err, HasSubstr(part));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Values, SweepBadInput,
    ::testing::Values(
        BadInput{"NanCoordinate", {"--a", "nan,0,1"}, {"--a", "\"nan,0,1\"", "not a finite"}},
        BadInput{"InfiniteMovement", {"--va", "inf,0"}, {"--va", "\"inf,0\"", "not a finite"}},
        BadInput{"NegativeInfinity", {"--vb", "-inf,0"}, {"--vb", "-inf,0"}},
        BadInput{"HugeNumber", {"--b", "1e999,0,1"}, {"--b", "1e999", "range"}},
        BadInput{"ZeroRadius", {"--a", "0,0,0"}, {"--a", "\"0,0,0\"", "radius"}},
        BadInput{"NegativeRadius", {"--b", "8,3,-1.5"}, {"--b", "\"8,3,-1.5\"", "radius"}},
        BadInput{"ZeroMass", {"--ma", "0"}, {"--ma", "\"0\"", "> 0"}},
        BadInput{"NegativeMass", {"--mb", "-1"}, {"--mb", "\"-1\""}},
        BadInput{"NanMass", {"--ma", "nan"}, {"--ma", "\"nan\""}},
        BadInput{"NegativeInfiniteMass", {"--ma", "-inf"}, {"--ma", "\"-inf\""}},
        BadInput{"WordMass", {"--mb", "heavy"}, {"--mb", "\"heavy\""}},
        BadInput{"BothImmovable",
                 {"--ma", "immovable", "--mb", "inf"},
                 {"--mb", "\"inf\"", "immovable"}},
        BadInput{"RestitutionAboveOne", {"--e", "1.5"}, {"--e", "\"1.5\"", "[0, 1]"}},
        BadInput{"RestitutionBelowZero", {"--e", "-0.1"}, {"--e", "\"-0.1\""}},
        BadInput{"RestitutionNan", {"--e", "nan"}, {"--e", "\"nan\""}},
        BadInput{"TooFewNumbers", {"--a", "1,2"}, {"--a", "\"1,2\"", "X,Y,R"}},
        BadInput{"TooManyNumbers", {"--va", "1,2,3"}, {"--va", "\"1,2,3\"", "DX,DY"}},
        BadInput{"NotANumber", {"--a", "1,2,x"}, {"--a", "\"1,2,x\"", "\"x\" is not a number"}},
        BadInput{"EmptyPart", {"--a", "1,,2"}, {"--a", "\"1,,2\"", "part 2 is empty"}},
        BadInput{"TrailingComma", {"--vb", "1,"}, {"--vb", "\"1,\"", "part 2 is empty"}},
        BadInput{"TrailingCharacters", {"--b", "8,3,1.5x"}, {"--b", "\"1.5x\""}},
        BadInput{"Spaces", {"--a", "0, 0, 1"}, {"--a", "\"0, 0, 1\""}},
        BadInput{"EmptyValue", {"--va", ""}, {"--va", "empty"}},
        BadInput{"MissingOption", {"--b", "<drop>"}, {"--b", "required", "--help"}},
        BadInput{"UnknownOption", {"--frobnicate", "3"}, {"--frobnicate", "--help"}},
        BadInput{"StrayWord", {"extra"}, {"extra", "--help"}}),
    [](const ::testing::TestParamInfo<BadInput>& param) { return param.param.name; });

// The library checks masses only in bounce(), which runs only on a hit; the tool checks them
// always.
TEST(SweepErrors, BadMassIsAnErrorEvenWithoutAHit) {
  const ToolRun run = run_carom(
      {"sweep", "--a", "0,0,1", "--va", "6,2", "--b", "8,3,1.5", "--vb", "-4,2", "--ma", "0"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("--ma"));
}

TEST(SweepErrors, BadInputWithJsonPrintsNoJson) {
  const ToolRun run = run_carom(
      {"sweep", "--a", "0,0,-1", "--va", "6,2", "--b", "8,3,1.5", "--vb", "-4,2", "--json"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
}

TEST(ToolErrors, NoVerbIsAUsageError) {
  const ToolRun run = run_carom({});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("--help"));
}

TEST(ToolErrors, UnknownVerbIsAUsageError) {
  const ToolRun run = run_carom({"frobnicate"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_THAT(run.err, HasSubstr("frobnicate"));
}

}  // namespace
}  // namespace carom::cli::test
