// carom tool: the MPI job this process is a rank of. A tool built with MPI (Open MPI from Debian;
// CAROM_MPI) and started by mpirun or srun with more than one process joins the job on first
// use and leaves it when the program ends. Started any other way, or built without MPI, it is a
// job of one rank and makes no MPI call, so a plain `carom eos` never needs an MPI runtime.
#pragma once

#include <string>
#include <vector>

namespace carom::cli {

class MpiJob {
 public:
  // The job, joined on the first call (from the main thread).
  [[nodiscard]] static const MpiJob& get();

  [[nodiscard]] int rank() const noexcept { return rank_; }
  [[nodiscard]] int size() const noexcept { return size_; }
  [[nodiscard]] bool is_root() const noexcept { return rank_ == 0; }

  // Collective (every rank calls it, from the main thread): at rank 0 every rank's text in rank
  // order, at the others nothing.
  [[nodiscard]] std::vector<std::string> gather(const std::string& mine) const;
  // Collective: rank 0's text at every rank.
  [[nodiscard]] std::string broadcast(const std::string& from_root) const;

 private:
  MpiJob();
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace carom::cli
