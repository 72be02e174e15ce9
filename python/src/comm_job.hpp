// carom for Python: an mpi4py communicator as the job a sweep's runs are shared among
// (system/ensemble_job.hpp). Any object with Get_rank(), Get_size(), bcast(obj, root=0) and
// gather(obj, root=0) will do; its calls are made holding the GIL, from the thread that runs the
// sweep, which is the one every rank's collective calls must come from.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "system/ensemble_job.hpp"

namespace carom::python {

class CommJob final : public cli::EnsembleJob {
 public:
  // Reads the rank and size (holding the GIL); a comm without them raises TypeError.
  explicit CommJob(pybind11::object comm);
  // The comm is let go holding the GIL.
  ~CommJob() override;
  CommJob(const CommJob&) = delete;
  CommJob& operator=(const CommJob&) = delete;
  CommJob(CommJob&&) = delete;
  CommJob& operator=(CommJob&&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }
  [[nodiscard]] std::vector<std::string> gather(const std::string& mine) const override;
  [[nodiscard]] std::string broadcast(const std::string& from_root) const override;

 private:
  pybind11::object comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace carom::python
