#include "system/mpi_job.hpp"

#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string_view>

#if CAROM_HAVE_MPI
#include <mpi.h>
#endif

namespace carom::cli {
namespace mpi_job_start {

// Whether a launcher started this process as one of several: Open MPI's mpirun
// (OMPI_COMM_WORLD_SIZE), a PMI launcher such as MPICH's or Slurm's srun (PMI_SIZE), or srun with
// PMIx (SLURM_NTASKS inside a job step).
bool started_as_one_of_several() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) > 1) return true;
  }
  const char* tasks = std::getenv("SLURM_NTASKS");
  return std::getenv("SLURM_STEP_ID") != nullptr && tasks != nullptr && std::atoi(tasks) > 1;
}

#if CAROM_HAVE_MPI
void leave() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized == 0) MPI_Finalize();
}

int length_of(const std::string& text) {
  if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::length_error("an MPI message of more than 2 GiB");
  }
  return static_cast<int>(text.size());
}
#endif

}  // namespace mpi_job_start

MpiJob::MpiJob() {
#if CAROM_HAVE_MPI
  if (!mpi_job_start::started_as_one_of_several()) return;
  // Only the main thread calls MPI; the worker threads run worlds.
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit(&mpi_job_start::leave);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
#endif
}

const MpiJob& MpiJob::get() {
  static const MpiJob job;
  return job;
}

std::vector<std::string> MpiJob::gather(const std::string& mine) const {
  if (size_ == 1) return {mine};
#if CAROM_HAVE_MPI
  const int length = mpi_job_start::length_of(mine);
  std::vector<int> lengths(is_root() ? static_cast<std::size_t>(size_) : 0U);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> offsets(lengths.size());
  long long total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    offsets[r] = static_cast<int>(total);
    total += lengths[r];
  }
  if (total > std::numeric_limits<int>::max()) {
    throw std::length_error("MPI results of more than 2 GiB at rank 0");
  }
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
              0, MPI_COMM_WORLD);
  std::vector<std::string> texts;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    texts.emplace_back(std::string_view(all).substr(static_cast<std::size_t>(offsets[r]),
                                                    static_cast<std::size_t>(lengths[r])));
  }
  return texts;
#else
  return {mine};
#endif
}

std::string MpiJob::broadcast(const std::string& from_root) const {
  if (size_ == 1) return from_root;
#if CAROM_HAVE_MPI
  int length = is_root() ? mpi_job_start::length_of(from_root) : 0;
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string text = is_root() ? from_root : std::string(static_cast<std::size_t>(length), '\0');
  MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return text;
#else
  return from_root;
#endif
}

}  // namespace carom::cli
