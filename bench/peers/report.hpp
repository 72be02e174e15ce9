// carom peers benchmark: the whole comparison, each case in a process of its own (this program
// run again with `run`), collected into a Markdown report (docs/peers.md).
#pragma once

#include <string>
#include <vector>

namespace carom::peers {

struct ReportOptions {
  std::string out;                   // the Markdown file; empty: standard output
  std::vector<std::string> engines;  // empty: every engine this build has
  bool quick = false;                // N = 10³ and 10⁴ only, 120 steps: for trying the harness
  bool smoke = false;                // N = 200, a few steps: the test that every part runs
  std::string command;               // the command to print in the report as the one that made it
};

// Runs every case and writes the report; returns the process's exit status (non-zero when a case
// failed to run, after writing what it has).
int write_report(const ReportOptions& options, const std::string& self);

}  // namespace carom::peers
