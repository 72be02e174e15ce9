// carom tool: the MPI job this process is a rank of. A tool built with MPI (Open MPI from Debian;
// CAROM_MPI) and started by mpirun or srun with more than one process joins the job on first
// use and leaves it when the program ends. Started any other way, or built without MPI, it is a
// job of one rank and makes no MPI call, so a plain `carom eos` never needs an MPI runtime.
#pragma once

#include <string>
#include <vector>

#include "system/ensemble_job.hpp"

namespace carom::cli {

class MpiJob final : public EnsembleJob {
 public:
  // The job, joined on the first call (from the main thread).
  [[nodiscard]] static const MpiJob& get();

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }

  // Collective over MPI_COMM_WORLD, from the main thread only.
  [[nodiscard]] std::vector<std::string> gather(const std::string& mine) const override;
  [[nodiscard]] std::string broadcast(const std::string& from_root) const override;

 private:
  MpiJob();
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace carom::cli
