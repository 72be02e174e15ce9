// carom tool: the runs of an equation-of-state sweep (`carom eos`), with checkpoints: given a
// folder, every run that ends is kept there at once (gas_record.hpp), and a run whose file is
// already there, for the very same gas, run length and seed, is read instead of run again. A
// sweep stopped by a signal, or killed, goes on from where it was when started again with the
// same options and folder, and gives the same numbers as one never stopped.
//
// Shared among processes (system/ensemble_job.hpp: the ranks of an MPI job, or of an mpi4py
// communicator from Python) rank 0 reads the checkpoints and hands out the runs still to
// make, every size-th to each rank, which runs its share on its own threads and keeps each run's
// checkpoint as it ends (the folder must be one every rank sees: a shared file system). The
// runs' numbers are then gathered at rank 0 exactly (gas_record.hpp), which alone writes the
// outputs: the same files as a sweep on one machine, bit for bit.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gas/gas_points.hpp"
#include "system/ensemble_job.hpp"

namespace carom::cli {

struct EosSweepOutcome {
  bool leads = true;                    // rank 0 (or no MPI): the one that writes the outputs
  GasPointsOutcome runs;                // every run, in the specs' order (read ones completed)
  std::size_t read = 0;                 // how many were read from their checkpoint files
  std::vector<std::string> not_kept{};  // checkpoint files that could not be written, and why
};

// Runs the specs shared among the job's processes, on `threads` threads in each (gas_points.hpp);
// points_folder empty: no checkpoints. Only where `leads` are the runs filled in. `watch` is told
// of this process's progress (the tool gives one to rank 0 only, for its progress bar).
[[nodiscard]] EosSweepOutcome run_sweep(const std::vector<GasSpec>& specs, std::size_t threads,
                                        const std::string& points_folder, const GasStopAsked& stop,
                                        const GasPointsWatch& watch, const EnsembleJob& job);

}  // namespace carom::cli
