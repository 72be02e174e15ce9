#include "pack/pack_ensemble.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>

#include "carom/scene.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "pack/packed_scene.hpp"
#include "system/output_file.hpp"
#include "system/parallel_runs.hpp"

namespace carom::cli {
namespace pack_ensemble_parts {

// What decides a packing: a checkpoint is read only for the very same options and seed.
nlohmann::json run_key(const PackRequest& r) {
  const science::PackingSpec& spec = r.spec;
  return {
      {"n", spec.n},
      {"second_diameter", spec.second_diameter},
      {"second_fraction", spec.second_fraction},
      {"boundary", spec.boundary == Boundary::periodic ? "periodic" : "box"},
      {"aspect", spec.aspect},
      {"start_eta", spec.start_eta},
      {"sized_for_eta", spec.sized_for_eta},
      {"seed", spec.seed},
      {"rate", r.settings.rate},
      {"target_eta", r.settings.target_eta},
      {"pressure_limit", r.settings.pressure_limit},
      {"window_collisions", r.settings.window_collisions},
      {"collision_limit", r.settings.collision_limit},
      {"contact_tolerance", r.tolerance ? nlohmann::json(*r.tolerance) : nlohmann::json(nullptr)}};
}

std::string scene_path(const std::string& folder, std::uint64_t seed) {
  return (std::filesystem::path(folder) / ("seed-" + std::to_string(seed) + ".json")).string();
}

std::string checkpoint_path(const std::string& folder, std::uint64_t seed) {
  return (std::filesystem::path(folder) / "runs" / ("seed-" + std::to_string(seed) + ".json"))
      .string();
}

// Whether a kept report has every figure the ensemble's report reads, of its type.
bool report_complete(const nlohmann::json& report) {
  if (!report.is_object()) return false;
  for (const char* number : {"eta", "Z", "psi6", "pressure"}) {
    if (!report.contains(number) || !report[number].is_number()) return false;
  }
  for (const char* count : {"n", "rattlers"}) {
    if (!report.contains(count) || !report[count].is_number_unsigned()) return false;
  }
  return report.contains("end") && report["end"].is_string() && report.contains("jammed") &&
         report["jammed"].is_boolean();
}

// The report kept for this very key, or nothing (no file, another run's, one cut short or
// altered: each is compressed again).
std::optional<nlohmann::json> read_checkpoint(const std::string& path, const nlohmann::json& key) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  const nlohmann::json kept = nlohmann::json::parse(in, nullptr, false);
  if (kept.is_discarded() || !kept.is_object() || !kept.contains("carom_pack_run") ||
      kept["carom_pack_run"] != 1 || !kept.contains("key") || kept["key"] != key ||
      !kept.contains("report") || !report_complete(kept["report"])) {
    return std::nullopt;
  }
  return kept["report"];
}

PackOptions with_seed(const PackOptions& o, std::uint64_t seed) {
  PackOptions mine = o;
  mine.seed = std::to_string(seed);
  mine.out.clear();
  mine.picture.clear();
  return mine;
}

struct Estimate {
  double mean = 0.0;
  std::optional<double> seed_error;  // none for one value
};

Estimate estimate(const std::vector<double>& values) {
  Estimate e;
  if (values.empty()) return e;
  double sum = 0.0;
  for (const double v : values) sum += v;
  const auto k = static_cast<double>(values.size());
  e.mean = sum / k;
  if (values.size() > 1) {
    double squares = 0.0;
    for (const double v : values) squares += (v - e.mean) * (v - e.mean);
    e.seed_error = std::sqrt(squares / (k - 1.0) / k);
  }
  return e;
}

// The completed runs' values of one report field (rattlers as a fraction of the disks).
std::vector<double> values_of(const std::vector<PackRun>& runs, const std::string& field) {
  std::vector<double> values;
  for (const PackRun& run : runs) {
    if (!run.completed) continue;
    const nlohmann::json& r = run.report;
    values.push_back(field == "rattler_fraction"
                         ? r.at("rattlers").get<double>() / r.at("n").get<double>()
                         : r.at(field).get<double>());
  }
  return values;
}

// The values the ensemble averages, as the JSON names them.
constexpr std::array<const char*, 5> kEstimated{"eta", "Z", "rattler_fraction", "psi6", "pressure"};

}  // namespace pack_ensemble_parts

PackEnsembleOutcome run_pack_ensemble(const PackOptions& o, std::uint64_t seeds,
                                      std::size_t threads, const std::string& folder,
                                      const std::function<bool()>& stop,
                                      const std::function<void(double)>& watch,
                                      const EnsembleJob& job) {
  namespace parts = pack_ensemble_parts;
  const std::uint64_t first_seed = parse_pack_options(o).spec.seed;
  if (seeds > 0 && seeds - 1 > std::numeric_limits<std::uint64_t>::max() - first_seed) {
    throw UsageError("--seeds", std::to_string(seeds),
                     "the last seed would pass 2^64 - 1 (from --seed " + o.seed + ")");
  }
  std::vector<PackRequest> requests;
  for (std::uint64_t k = 0; k < seeds; ++k) {
    requests.push_back(parse_pack_options(parts::with_seed(o, first_seed + k)));
  }
  PackEnsembleOutcome ensemble;
  ensemble.leads = job.is_root();
  ensemble.runs.resize(seeds);
  for (std::uint64_t k = 0; k < seeds; ++k) ensemble.runs[k].seed = first_seed + k;
  // Rank 0 reads the checkpoints; the rest are shared out.
  std::vector<std::size_t> to_make;
  if (job.is_root()) {
    for (std::size_t k = 0; k < seeds; ++k) {
      std::optional<nlohmann::json> kept;
      if (!folder.empty()) {
        kept = parts::read_checkpoint(parts::checkpoint_path(folder, ensemble.runs[k].seed),
                                      parts::run_key(requests[k]));
      }
      if (kept) {
        ensemble.runs[k].report = std::move(*kept);
        ensemble.runs[k].completed = true;
        ++ensemble.read;
      } else {
        to_make.push_back(k);
      }
    }
  }
  const std::vector<std::size_t> mine = share_of_runs(job, to_make);
  std::vector<PackRun> made(mine.size());
  std::atomic<bool> stopped{false};
  const auto stop_once = [&] {
    if (!stopped.load() && stop && stop()) stopped.store(true);
    return stopped.load();
  };
  std::mutex shared;
  run_in_parallel(
      mine.size(), threads, stop_once,
      [&](std::size_t j, std::atomic<double>& progress) {
        const std::size_t k = mine[j];
        PackRun& run = made[j];
        run.seed = ensemble.runs[k].seed;
        try {
          const PackOptions options = parts::with_seed(o, run.seed);
          const PackRequest& r = requests[k];
          const PackOutcome outcome =
              run_pack_session(options, r, {}, [&](const science::CompressionProgress& p) {
                progress.store(std::clamp(progress_fraction(r, p), 0.0, 1.0));
                return stop_once();
              });
          if (outcome.result.end != science::CompressionEnd::interrupted) {
            run.report = pack_json(options, r, outcome);
            run.completed = true;
            if (!folder.empty()) {
              const Scene scene =
                  packed_scene(outcome.world, description_of(options, outcome.result));
              const nlohmann::json kept{
                  {"carom_pack_run", 1}, {"key", parts::run_key(r)}, {"report", run.report}};
              // The scene first: a checkpoint means its packing is written too.
              std::optional<std::string> failure =
                  write_output(parts::scene_path(folder, run.seed), to_json_text(scene));
              if (!failure) {
                failure = write_output(parts::checkpoint_path(folder, run.seed), kept.dump());
              }
              if (failure) {
                const std::lock_guard<std::mutex> lock(shared);
                ensemble.not_kept.push_back("seed " + std::to_string(run.seed) + ": " + *failure);
              }
            }
          }
        } catch (const std::exception& error) {
          run.failure = error.what();
        }
      },
      watch);
  // Every rank's packings at rank 0, their reports exactly (JSON numbers to the bit).
  nlohmann::json messages = nlohmann::json::array();
  for (std::size_t j = 0; j < mine.size(); ++j) {
    nlohmann::json message{{"index", mine[j]}, {"completed", made[j].completed}};
    if (!made[j].failure.empty()) message["failure"] = made[j].failure;
    if (made[j].completed) message["report"] = made[j].report;
    messages.push_back(std::move(message));
  }
  for (const std::string& text : job.gather(messages.dump())) {
    for (const nlohmann::json& message : nlohmann::json::parse(text)) {
      PackRun& run = ensemble.runs.at(message.at("index").get<std::size_t>());
      run.completed = message.at("completed").get<bool>();
      if (message.contains("failure")) run.failure = message["failure"].get<std::string>();
      if (run.completed) run.report = message.at("report");
    }
  }
  return ensemble;
}

nlohmann::json pack_ensemble_json(const std::vector<PackRun>& runs) {
  namespace parts = pack_ensemble_parts;
  nlohmann::json out;
  out["seeds"] = runs.size();
  out["first_seed"] = runs.empty() ? 0 : runs.front().seed;
  nlohmann::json reports = nlohmann::json::array();
  std::size_t jammed = 0;
  for (const PackRun& run : runs) {
    if (!run.completed) continue;
    reports.push_back(run.report);
    if (run.report.value("jammed", false)) ++jammed;
  }
  out["n"] = reports.empty() ? nlohmann::json(nullptr) : reports.front().at("n");
  out["completed"] = reports.size();
  out["jammed"] = jammed;
  for (const char* field : parts::kEstimated) {
    const parts::Estimate e = parts::estimate(parts::values_of(runs, field));
    out[field] = reports.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.mean);
    out[std::string(field) + "_seed_err"] =
        e.seed_error ? nlohmann::json(*e.seed_error) : nlohmann::json(nullptr);
  }
  out["runs"] = std::move(reports);
  return out;
}

std::string pack_ensemble_text(const std::vector<PackRun>& runs) {
  namespace parts = pack_ensemble_parts;
  std::ostringstream out;
  const nlohmann::json summary = pack_ensemble_json(runs);
  out << summary["completed"].get<std::size_t>() << " of " << runs.size() << " packings";
  if (!runs.empty()) {
    out << " (seeds " << runs.front().seed << " to " << runs.back().seed << ")";
  }
  if (!summary["n"].is_null()) out << " of " << summary["n"].get<std::uint64_t>() << " disks";
  out << ", " << summary["jammed"].get<std::size_t>() << " jammed\n";
  out << fmt::format("  {:>6}  {:>16}  {:>8}  {:>8}  {:>8}  {:>12}  {}\n", "seed",
                     "packing fraction", "Z", "rattlers", "psi6", "pressure Z", "end");
  for (const PackRun& run : runs) {
    if (!run.completed) continue;
    const nlohmann::json& r = run.report;
    out << fmt::format("  {:>6}  {:>16}  {:>8}  {:>8}  {:>8}  {:>12}  {}\n", run.seed,
                       readable(r.at("eta").get<double>()), rounded(r.at("Z").get<double>()),
                       r.at("rattlers").get<std::uint64_t>(), rounded(r.at("psi6").get<double>()),
                       rounded(r.at("pressure").get<double>()), r.at("end").get<std::string>());
  }
  if (summary["completed"].get<std::size_t>() == 0) return out.str();
  out << "  mean over the seeds, with the standard error between them:\n";
  for (const char* field : parts::kEstimated) {
    const nlohmann::json& error = summary[std::string(field) + "_seed_err"];
    out << fmt::format("    {:<17} {}{}\n", field, readable(summary[field].get<double>()),
                       error.is_null() ? std::string() : " +- " + rounded(error.get<double>()));
  }
  return out.str();
}

}  // namespace carom::cli
