// carom tool: `carom pack --seeds K`: K packings made alike from consecutive seeds, and what they
// share (the mean packing fraction, contact number, rattlers and ψ₆, each with the standard error
// between the seeds: how far one packing's jamming point is from the ensemble's).
//
// The packings run on threads, and shared among an ensemble job's processes (an MPI job's ranks,
// system/ensemble_job.hpp) as `carom eos` shares its runs: rank 0 reads the checkpoints and hands
// out the seeds still to make, every size-th to each rank; each report comes back to rank 0
// exactly. Given a folder, each packing is written there as it ends (seed-S.json, a scene) with
// its report (runs/seed-S.json, the checkpoint); a seed whose checkpoint is there, for the very
// same options, is read instead of compressed again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pack/pack_session.hpp"
#include "system/ensemble_job.hpp"

namespace carom::cli {

// (nlohmann::json's move is noexcept; the check sees the assertions of its invariant inside.)
struct PackRun {  // NOLINT(bugprone-exception-escape)
  std::uint64_t seed = 0;
  nlohmann::json report;  // pack_json's, once the packing ended (completed)
  std::string failure;    // its error, where it failed
  bool completed = false;
};

struct PackEnsembleOutcome {
  bool leads = true;                    // rank 0 (or no MPI): the one that reports
  std::vector<PackRun> runs;            // in seed order (filled in where `leads`)
  std::size_t read = 0;                 // how many were read from their checkpoints
  std::vector<std::string> not_kept{};  // packings or checkpoints that could not be written
};

// `o` with `seeds` seeds from o.seed on (o.out and o.picture are not read), on `threads`
// threads in each process; folder empty: nothing written or read. `stop` is asked by every
// compression; `watch` is told this process's progress (0 to 1) about ten times a second, on the
// calling thread. Throws UsageError for a bad option (checked before anything runs).
[[nodiscard]] PackEnsembleOutcome run_pack_ensemble(const PackOptions& o, std::uint64_t seeds,
                                                    std::size_t threads, const std::string& folder,
                                                    const std::function<bool()>& stop,
                                                    const std::function<void(double)>& watch,
                                                    const EnsembleJob& job);

// {"seeds", "first_seed", "n", "completed", "jammed", then "eta", "Z", "rattler_fraction",
// "psi6", "pressure", each with its "_seed_err" (the seeds' standard deviation / √K; null for
// one seed), over the completed runs, and "runs": [one pack_json per completed seed]}.
[[nodiscard]] nlohmann::json pack_ensemble_json(const std::vector<PackRun>& runs);
// A table a seed, and the means with their errors between the seeds.
[[nodiscard]] std::string pack_ensemble_text(const std::vector<PackRun>& runs);

}  // namespace carom::cli
