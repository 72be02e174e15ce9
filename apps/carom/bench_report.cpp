#include "bench_report.hpp"

#include <fmt/format.h>

#include "readable_number.hpp"

namespace carom::cli {

std::string bench_text(const BenchOutcome& o) {
  std::string out;
  out += fmt::format("{} equal disks (diameter 1), packing fraction {}, periodic box {} x {}\n",
                     o.n, readable(o.eta), readable(o.box_side), readable(o.box_side));
  out += fmt::format("  start: triangular lattice of {} x {} sites, velocities from seed {}\n",
                     o.lattice_columns, o.lattice_rows, o.seed);
  out += fmt::format("  setup {} s, equilibration {} collisions in {} s (neither timed)\n",
                     readable(o.setup_seconds), o.equilibration_collisions,
                     readable(o.equilibration_seconds));
  out += fmt::format("  timed: {} collisions in {} s = {} collisions/s ({} ns per collision)\n",
                     o.collisions, readable(o.wall_seconds), readable(o.collisions_per_second()),
                     readable(o.nanoseconds_per_collision()));
  out +=
      fmt::format("  memory: {} bytes per ball (peak resident set growth, contact recording off)\n",
                  readable(o.bytes_per_ball()));
  out += fmt::format("  drift over the timed run: energy {}, momentum {} (relative)\n",
                     readable(o.energy_drift), readable(o.momentum_drift));
  out += fmt::format("  build: {}, {}\n", o.build_type.empty() ? "(no build type)" : o.build_type,
                     o.compiler);
  return out;
}

nlohmann::ordered_json bench_json(const BenchOutcome& o) {
  nlohmann::ordered_json out;
  out["n"] = o.n;
  out["eta"] = o.eta;
  out["seed"] = o.seed;
  out["box_side"] = o.box_side;
  out["lattice_columns"] = o.lattice_columns;
  out["lattice_rows"] = o.lattice_rows;
  out["setup_seconds"] = o.setup_seconds;
  out["equilibration_collisions"] = o.equilibration_collisions;
  out["equilibration_seconds"] = o.equilibration_seconds;
  out["collisions"] = o.collisions;
  out["wall_seconds"] = o.wall_seconds;
  out["collisions_per_second"] = o.collisions_per_second();
  out["nanoseconds_per_collision"] = o.nanoseconds_per_collision();
  out["bytes_per_ball"] = o.bytes_per_ball();
  out["peak_rss_growth_bytes"] = o.peak_rss_growth_bytes;
  out["energy_drift"] = o.energy_drift;
  out["momentum_drift"] = o.momentum_drift;
  out["build_type"] = o.build_type;
  out["compiler"] = o.compiler;
  return out;
}

}  // namespace carom::cli
