#include "gas/eos_sweep.hpp"

#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "gas/gas_record.hpp"

namespace carom::cli {
namespace eos_sweep_parts {

// What a rank tells rank 0 of one of its runs.
nlohmann::json run_message(std::size_t index, const GasPointsOutcome& ran, std::size_t j) {
  nlohmann::json message{{"index", index}, {"completed", ran.completed[j] != 0}};
  if (ran.failures[j]) {
    try {
      std::rethrow_exception(ran.failures[j]);
    } catch (const std::exception& error) {
      message["failure"] = error.what();
    }
  } else {
    message["record"] = gas_record(ran.outcomes[j]);
  }
  return message;
}

}  // namespace eos_sweep_parts

EosSweepOutcome run_sweep(const std::vector<GasSpec>& specs, std::size_t threads,
                          const std::string& points_folder, const GasStopAsked& stop,
                          const GasPointsWatch& watch, const EnsembleJob& job) {
  const auto file_of = [&points_folder](const GasSpec& spec) {
    return (std::filesystem::path(points_folder) / point_file_name(spec)).string();
  };
  EosSweepOutcome sweep;
  sweep.leads = job.is_root();
  GasPointsOutcome& all = sweep.runs;
  all.outcomes.resize(specs.size());
  all.failures.resize(specs.size());
  all.completed.assign(specs.size(), 0);
  // Rank 0 reads the checkpoints and decides which runs to make; every rank learns the list.
  std::vector<std::size_t> to_make;
  if (job.is_root()) {
    for (std::size_t i = 0; i < specs.size(); ++i) {
      std::optional<GasOutcome> kept;
      if (!points_folder.empty()) kept = read_point_file(file_of(specs[i]), specs[i]);
      if (kept) {
        all.outcomes[i] = *kept;
        all.completed[i] = 1;
        ++sweep.read;
      } else {
        to_make.push_back(i);
      }
    }
  }
  // This rank's share of them.
  const std::vector<std::size_t> index_of = share_of_runs(job, to_make);
  std::vector<GasSpec> mine;
  mine.reserve(index_of.size());
  for (const std::size_t i : index_of) mine.push_back(specs[i]);
  std::mutex not_kept;
  GasPointDone keep;
  if (!points_folder.empty()) {
    keep = [&](std::size_t j, const GasOutcome& outcome) {
      if (auto failure = write_point_file(file_of(mine[j]), mine[j], outcome)) {
        const std::lock_guard<std::mutex> lock(not_kept);
        sweep.not_kept.push_back(std::move(*failure));
      }
    };
  }
  GasPointsOutcome ran = run_gas_points(mine, threads, stop, watch, keep);
  all.stopped = ran.stopped;
  if (job.size() == 1) {
    for (std::size_t j = 0; j < mine.size(); ++j) {
      const std::size_t i = index_of[j];
      all.outcomes[i] = std::move(ran.outcomes[j]);
      all.failures[i] = ran.failures[j];
      all.completed[i] = ran.completed[j];
    }
    return sweep;
  }
  // Every rank's runs, gathered at rank 0: the same numbers as runs made there.
  nlohmann::json messages = nlohmann::json::array();
  for (std::size_t j = 0; j < mine.size(); ++j) {
    messages.push_back(eos_sweep_parts::run_message(index_of[j], ran, j));
  }
  for (const std::string& text : job.gather(messages.dump())) {
    for (const nlohmann::json& message : nlohmann::json::parse(text)) {
      const auto i = message.at("index").get<std::size_t>();
      all.completed[i] = message.at("completed").get<bool>() ? 1 : 0;
      if (message.contains("failure")) {
        all.failures[i] =
            std::make_exception_ptr(std::runtime_error(message.at("failure").get<std::string>()));
      } else {
        all.outcomes[i] = gas_outcome_from_record(message.at("record"));
      }
    }
  }
  return sweep;
}

}  // namespace carom::cli
