#include "drawing/render_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "drawing/svg_plot.hpp"
#include "options/readable_number.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

struct Sample {
  double time;  // since the start
  double energy;
  Vec2 momentum;
  double potential;  // of gravity; 0 without it
};

struct Run {
  std::vector<Sample> samples;
  std::vector<ContactEvent> contacts;
  std::vector<PottedBall> potted;
  double start_time = 0.0;
};

Run run_scene(const Scene& scene, double until) {
  SceneWorld scene_world = make_world(scene);
  // A signal stops the run: the plot then ends at the time reached.
  stop_world_on_signals(scene_world.world);
  Run run;
  run.start_time = scene_world.start_time;
  const auto sample = [&] {
    run.samples.push_back({scene_world.world.time(), scene_world.world.kinetic_energy(),
                           scene_world.world.momentum(), scene_world.world.potential_energy()});
  };
  sample();
  for (int i = 1; i <= kPlotSamples; ++i) {
    const double target = until * (static_cast<double>(i) / kPlotSamples);
    step_scene(scene_world, target - scene_world.world.time(), &run.contacts, &run.potted);
    sample();
    if (scene_world.world.stop_reason() == StopReason::interrupted) break;
  }
  return run;
}

std::string energy_unit(const SceneUnits& u) {
  return u.mass + "·" + u.length + "²/" + u.time + "²";
}

TimePlotSpec energy_plot(const Scene& scene, const Run& run) {
  TimePlotSeries series{"kinetic energy", "#1f4e9c", {}, false};
  const double e0 = run.samples.front().energy;
  double drift = 0.0;
  for (const Sample& s : run.samples) {
    series.points.push_back({s.time, s.energy});
    drift = std::max(drift, std::abs(s.energy - e0));
  }
  const std::string change = e0 > 0.0
                                 ? "largest change |E(t) − E(0)| / E(0) = " + readable(drift / e0)
                                 : "largest change |E(t) − E(0)| = " + readable(drift);
  return {"Kinetic energy",
          change + (run.potted.empty() ? "" : "; potted balls take theirs away"),
          "time (" + scene.units.time + ")",
          "energy (" + energy_unit(scene.units) + ")",
          {series},
          true};
}

// With gravity the kinetic energy rises and falls as the balls do: the total is what is kept.
TimePlotSpec energies_plot(const Scene& scene, const Run& run) {
  TimePlotSeries kinetic{"kinetic energy", "#1f4e9c", {}, false};
  TimePlotSeries potential{"potential energy", "#c03030", {}, false};
  TimePlotSeries total{"total energy", "#202020", {}, false};
  const Sample& first = run.samples.front();
  const double t0 = first.energy + first.potential;
  double drift = 0.0;
  double largest_kinetic = 0.0;
  for (const Sample& s : run.samples) {
    kinetic.points.push_back({s.time, s.energy});
    potential.points.push_back({s.time, s.potential});
    total.points.push_back({s.time, s.energy + s.potential});
    drift = std::max(drift, std::abs(s.energy + s.potential - t0));
    largest_kinetic = std::max(largest_kinetic, s.energy);
  }
  // The potential's zero is arbitrary, so the change is measured against the kinetic energy.
  const std::string change =
      largest_kinetic > 0.0
          ? "largest change |T(t) − T(0)| / max K = " + readable(drift / largest_kinetic)
          : "largest change |T(t) − T(0)| = " + readable(drift);
  return {"Energy",
          change + (run.potted.empty() ? "" : "; potted balls take theirs away"),
          "time (" + scene.units.time + ")",
          "energy (" + energy_unit(scene.units) + ")",
          {kinetic, potential, total},
          false};
}

TimePlotSpec momentum_plot(const Scene& scene, const Run& run) {
  TimePlotSeries x{"x", "#c03030", {}, false};
  TimePlotSeries y{"y", "#2060c0", {}, false};
  TimePlotSeries size{"length |p|", "#202020", {}, false};
  double drift = 0.0;
  const Vec2 p0 = run.samples.front().momentum;
  for (const Sample& s : run.samples) {
    x.points.push_back({s.time, s.momentum.x});
    y.points.push_back({s.time, s.momentum.y});
    size.points.push_back({s.time, length(s.momentum)});
    drift = std::max(drift, length(s.momentum - p0));
  }
  return {"Momentum",
          "largest change |p(t) − p(0)| = " + readable(drift) +
              " (walls and pockets take momentum; a periodic or open world keeps it)",
          "time (" + scene.units.time + ")",
          "momentum (" + scene.units.mass + "·" + scene.units.length + "/" + scene.units.time + ")",
          {x, y, size}};
}

TimePlotSpec rate_plot(const Scene& scene, const Run& run, double until) {
  const double width = until / kRateBins;
  std::vector<double> ball_ball(kRateBins, 0.0);
  std::vector<double> ball_wall(kRateBins, 0.0);
  std::vector<double> potted(kRateBins, 0.0);
  const auto bin = [&](double time) {
    return std::min(static_cast<std::size_t>(std::max(0.0, time / width)),
                    static_cast<std::size_t>(kRateBins - 1));
  };
  std::size_t pocket_contacts = 0;
  for (const ContactEvent& c : run.contacts) {
    (c.kind == ContactKind::ball_ball ? ball_ball : ball_wall)[bin(c.time)] += 1.0;
  }
  // A potting is no contact (a pocket's sensor removes the ball): a series of its own.
  for (const PottedBall& p : run.potted) {
    potted[bin(p.time - run.start_time)] += 1.0;
    ++pocket_contacts;
  }
  const auto series = [&](std::string name, std::string colour, const std::vector<double>& n) {
    TimePlotSeries s{std::move(name), std::move(colour), {}, true};
    for (int i = 0; i < kRateBins; ++i)
      s.points.push_back({i * width, n[static_cast<std::size_t>(i)] / width});
    s.points.push_back({until, n.back() / width});
    return s;
  };
  std::vector<TimePlotSeries> all{series("ball–ball", "#c03030", ball_ball),
                                  series("ball–wall", "#2060c0", ball_wall)};
  if (pocket_contacts > 0) all.push_back(series("potted", "#202020", potted));
  return {"Collisions per unit time",
          std::to_string(run.contacts.size()) +
              (run.contacts.size() == 1 ? " contact" : " contacts") + " in " + readable(until) +
              " " + scene.units.time + ", counted in " + std::to_string(kRateBins) + " bins of " +
              readable(width) + " " + scene.units.time,
          "time (" + scene.units.time + ")",
          "contacts per " + scene.units.time,
          all,
          true};
}

}  // namespace

std::string render_plot(const Scene& scene, PlotKind kind, double until, const std::string& title) {
  const Run run = run_scene(scene, until);
  TimePlotSpec spec;
  switch (kind) {
    case PlotKind::energy:
      spec = scene.world.gravity == Vec2{} ? energy_plot(scene, run) : energies_plot(scene, run);
      break;
    case PlotKind::momentum:
      spec = momentum_plot(scene, run);
      break;
    case PlotKind::rate:
      spec = rate_plot(scene, run, until);
      break;
  }
  spec.title = spec.title + ": " + title;
  return plot_svg(spec);
}

}  // namespace carom::cli
