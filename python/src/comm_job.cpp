#include "comm_job.hpp"

#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace carom::python {

CommJob::CommJob(py::object comm) : comm_(std::move(comm)) {
  for (const char* method : {"Get_rank", "Get_size", "bcast", "gather"}) {
    if (!py::hasattr(comm_, method)) {
      throw py::type_error(std::string("comm must be an mpi4py communicator (it has no ") + method +
                           "())");
    }
  }
  rank_ = comm_.attr("Get_rank")().cast<int>();
  size_ = comm_.attr("Get_size")().cast<int>();
  if (size_ < 1 || rank_ < 0 || rank_ >= size_) {
    throw py::value_error("comm: rank " + std::to_string(rank_) + " of " + std::to_string(size_) +
                          " processes");
  }
}

CommJob::~CommJob() {
  try {
    const py::gil_scoped_acquire locked;
    comm_ = py::object();
  } catch (...) {  // NOLINT(bugprone-empty-catch): the interpreter is going; nothing to release
  }
}

std::vector<std::string> CommJob::gather(const std::string& mine) const {
  const py::gil_scoped_acquire locked;
  const py::object all = comm_.attr("gather")(py::bytes(mine), py::arg("root") = 0);
  if (rank_ != 0) return {};
  std::vector<std::string> texts;
  for (const py::handle text : all) texts.push_back(text.cast<std::string>());
  return texts;
}

std::string CommJob::broadcast(const std::string& from_root) const {
  const py::gil_scoped_acquire locked;
  const py::object sent = rank_ == 0 ? py::object(py::bytes(from_root)) : py::object(py::none());
  return comm_.attr("bcast")(sent, py::arg("root") = 0).cast<std::string>();
}

}  // namespace carom::python
