// carom tool: the exit statuses every verb shares, so scripts can tell bad input from a failure.
#pragma once

namespace carom::cli {

inline constexpr int kExitSuccess = 0;
// Something went wrong that is not the caller's input: standard output could not be written,
// or an internal error.
inline constexpr int kExitFailure = 1;
// The command line was wrong: an unknown or missing option, a malformed or out-of-range value,
// an output file that cannot be written. The usual status for usage errors (as in BSD's EX_USAGE
// family and most GNU tools).
inline constexpr int kExitUsage = 2;
// A verb stopped by a signal, its outputs complete up to where it stopped: 128 + the signal, as
// shells report it (StopOnSignals::exit_code gives the one received).
inline constexpr int kExitInterrupted = 130;  // SIGINT, Ctrl-C
inline constexpr int kExitTerminated = 143;   // SIGTERM

}  // namespace carom::cli
