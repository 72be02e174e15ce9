// carom tool: the processes an ensemble of runs is shared among, and the two collective calls a
// sweep needs of them. MpiJob (system/mpi_job.hpp) is the tool's: the ranks of an MPI job, or
// this process alone. The Python module wraps an mpi4py communicator in one of its own.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace carom::cli {

class EnsembleJob {
 public:
  EnsembleJob() = default;
  EnsembleJob(const EnsembleJob&) = delete;
  EnsembleJob& operator=(const EnsembleJob&) = delete;
  EnsembleJob(EnsembleJob&&) = delete;
  EnsembleJob& operator=(EnsembleJob&&) = delete;
  virtual ~EnsembleJob() = default;

  [[nodiscard]] virtual int rank() const = 0;
  [[nodiscard]] virtual int size() const = 0;
  [[nodiscard]] bool is_root() const { return rank() == 0; }

  // Collective (every process calls it): at rank 0 every process's text in rank order, at the
  // others nothing.
  [[nodiscard]] virtual std::vector<std::string> gather(const std::string& mine) const = 0;
  // Collective: rank 0's text at every process.
  [[nodiscard]] virtual std::string broadcast(const std::string& from_root) const = 0;
};

// This process alone: rank 0 of 1.
class SingleProcessJob final : public EnsembleJob {
 public:
  [[nodiscard]] int rank() const override { return 0; }
  [[nodiscard]] int size() const override { return 1; }
  [[nodiscard]] std::vector<std::string> gather(const std::string& mine) const override {
    return {mine};
  }
  [[nodiscard]] std::string broadcast(const std::string& from_root) const override {
    return from_root;
  }
};

// Collective: the runs still to make, as rank 0 lists them (`to_make` is read at rank 0 only),
// shared out: this process's share, every size-th of them from its rank on, so that the runs of
// one point or seed range go to different processes.
[[nodiscard]] std::vector<std::size_t> share_of_runs(const EnsembleJob& job,
                                                     const std::vector<std::size_t>& to_make);

}  // namespace carom::cli
