#include "system/ensemble_job.hpp"

#include <nlohmann/json.hpp>

namespace carom::cli {

std::vector<std::size_t> share_of_runs(const EnsembleJob& job,
                                       const std::vector<std::size_t>& to_make) {
  std::vector<std::size_t> all = to_make;
  if (job.size() > 1) {
    all = nlohmann::json::parse(job.broadcast(nlohmann::json(to_make).dump()))
              .get<std::vector<std::size_t>>();
  }
  std::vector<std::size_t> mine;
  const auto ranks = static_cast<std::size_t>(job.size());
  for (std::size_t j = static_cast<std::size_t>(job.rank()); j < all.size(); j += ranks) {
    mine.push_back(all[j]);
  }
  return mine;
}

}  // namespace carom::cli
