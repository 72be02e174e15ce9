#include "commands/query_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "carom/scene.hpp"
#include "options/exit_codes.hpp"
#include "options/option_value.hpp"
#include "options/readable_number.hpp"
#include "options/usage_error.hpp"
#include "options/vector_args.hpp"
#include "run/scene_input.hpp"

namespace carom::cli {
namespace {

struct QueryOptions {
  std::string scene;
  std::string time;  // empty: the scene as it starts
  std::vector<std::string> rays;
  std::vector<std::string> casts;
  std::vector<std::string> points;
  std::vector<std::string> circles;
  std::vector<std::string> boxes;
  bool all = false;
  std::string ignore;
  std::string mask;
  bool json = false;
};

// A ball of the scene by name or index ("cue", "3").
BallId named_ball(const SceneWorld& sw, const std::string& text) {
  if (const auto it = sw.by_name.find(text); it != sw.by_name.end()) return it->second;
  const std::uint64_t index =
      parse_whole_number({"--ignore", text, "a ball's name or its index in the scene"});
  if (index >= sw.balls.size() || sw.balls[index].is_null()) {
    throw UsageError("--ignore", text,
                     "no such ball (the scene has " + std::to_string(sw.balls.size()) + ")");
  }
  return sw.balls[index];
}

// What a hit names, in the scene's terms: a ball by index (and name), a wall. (Pockets are
// sensors, which queries do not see.)
nlohmann::ordered_json hit_json(const SceneWorld& sw, const QueryHit& hit) {
  nlohmann::ordered_json out;
  if (hit.kind == HitKind::wall) {
    out["kind"] = "wall";
    out["wall"] = hit.wall;
  } else {
    const std::size_t index = sw.index_of(hit.ball).value_or(0);
    out["kind"] = "ball";
    out["ball"] = index;
    out["name"] =
        sw.scene.balls[index].name ? nlohmann::ordered_json(*sw.scene.balls[index].name) : nullptr;
  }
  out["fraction"] = hit.fraction;
  out["point"] = {hit.point.x, hit.point.y};
  out["normal"] = {hit.normal.x, hit.normal.y};
  out["center"] = {hit.center.x, hit.center.y};
  out["overlapping"] = hit.overlapping;
  return out;
}

nlohmann::ordered_json ids_json(const SceneWorld& sw, const std::vector<BallId>& ids) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const BallId id : ids) {
    if (const std::optional<std::size_t> index = sw.index_of(id)) out.push_back(*index);
  }
  return out;
}

std::string hit_text(const nlohmann::ordered_json& hit) {
  std::string what = hit["kind"].get<std::string>() + " ";
  what += hit["kind"] == "wall" ? std::to_string(hit["wall"].get<std::uint32_t>())
                                : std::to_string(hit["ball"].get<std::size_t>());
  if (hit.contains("name") && hit["name"].is_string())
    what += " \"" + hit["name"].get<std::string>() + "\"";
  return what + " at fraction " + readable(hit["fraction"].get<double>()) + ", point (" +
         readable(hit["point"][0].get<double>()) + ", " + readable(hit["point"][1].get<double>()) +
         "), centre (" + readable(hit["center"][0].get<double>()) + ", " +
         readable(hit["center"][1].get<double>()) + ")" +
         (hit["overlapping"].get<bool>() ? ", overlapping at the start" : "");
}

int run(const QueryOptions& options) {
  if (options.rays.empty() && options.casts.empty() && options.points.empty() &&
      options.circles.empty() && options.boxes.empty()) {
    throw UsageError("--ray", "", "give at least one of --ray, --ball, --point, --circle, --box");
  }
  const Scene scene = read_scene_argument(options.scene);
  SceneWorld sw = make_world(scene);
  if (!options.time.empty()) {
    const OptionValue value{"--time", options.time, "a scene time"};
    const double time = parse_finite_number(options.time, value);
    if (!(time >= scene.time)) {
      throw UsageError("--time", options.time,
                       "must be at or after the scene's time (" + readable(scene.time) + ")");
    }
    static_cast<void>(run_scene_until(sw, time - sw.start_time));
  }
  QueryFilter filter;
  if (!options.ignore.empty()) filter.ignore = named_ball(sw, options.ignore);
  if (!options.mask.empty()) {
    filter.mask = parse_whole_number({"--mask", options.mask, "category bits"});
  }
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  const auto add = [&](const char* kind, const std::string& text, nlohmann::ordered_json answer) {
    nlohmann::ordered_json entry;
    entry["query"] = kind;
    entry["value"] = text;
    entry["answer"] = std::move(answer);
    results.push_back(std::move(entry));
  };
  const auto hits_json = [&](const auto& hits) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const QueryHit& hit : hits) out.push_back(hit_json(sw, hit));
    return out;
  };
  for (const std::string& text : options.rays) {
    const std::vector<double> v = parse_number_list("--ray", text, "X,Y,DX,DY");
    const Vec2 origin{v[0], v[1]};
    const Vec2 move{v[2], v[3]};
    if (options.all) {
      add("ray", text, hits_json(sw.world.cast_ray_all(origin, move, filter)));
    } else {
      const QueryHit hit = sw.world.cast_ray(origin, move, filter);
      add("ray", text, hit ? hit_json(sw, hit) : nlohmann::ordered_json(nullptr));
    }
  }
  for (const std::string& text : options.casts) {
    const std::vector<double> v = parse_number_list("--ball", text, "X,Y,R,DX,DY");
    if (!(v[2] > 0.0)) throw UsageError("--ball", text, "the radius R must be > 0");
    const QueryHit hit = sw.world.cast_ball({v[0], v[1]}, v[2], {v[3], v[4]}, filter);
    add("ball", text, hit ? hit_json(sw, hit) : nlohmann::ordered_json(nullptr));
  }
  for (const std::string& text : options.points) {
    const Vec2 p = parse_vector("--point", text);
    add("point", text, ids_json(sw, sw.world.balls_at_point(p, filter)));
  }
  for (const std::string& text : options.circles) {
    const std::vector<double> v = parse_number_list("--circle", text, "X,Y,R");
    if (!(v[2] >= 0.0)) throw UsageError("--circle", text, "the radius R must be >= 0");
    add("circle", text, ids_json(sw, sw.world.balls_in_circle({v[0], v[1]}, v[2], filter)));
  }
  for (const std::string& text : options.boxes) {
    const std::vector<double> v = parse_number_list("--box", text, "X0,Y0,X1,Y1");
    if (!(v[0] <= v[2] && v[1] <= v[3])) {
      throw UsageError("--box", text, "X0 <= X1 and Y0 <= Y1");
    }
    add("box", text, ids_json(sw, sw.world.balls_in_box({v[0], v[1]}, {v[2], v[3]}, filter)));
  }
  if (options.json) {
    nlohmann::ordered_json out;
    out["scene"] = options.scene;
    out["time"] = sw.time();
    out["results"] = std::move(results);
    std::cout << out.dump() << '\n';
    return kExitSuccess;
  }
  std::cout << "scene time " << readable(sw.time()) << '\n';
  for (const nlohmann::ordered_json& entry : results) {
    std::cout << entry["query"].get<std::string>() << ' ' << entry["value"].get<std::string>()
              << ": ";
    const nlohmann::ordered_json& answer = entry["answer"];
    if (answer.is_null()) {
      std::cout << "nothing\n";
    } else if (answer.is_object()) {
      std::cout << hit_text(answer) << '\n';
    } else if (entry["query"] == "ray") {
      std::cout << answer.size() << " hits\n";
      for (const nlohmann::ordered_json& hit : answer) std::cout << "  " << hit_text(hit) << '\n';
    } else {
      std::cout << answer.dump() << '\n';
    }
  }
  return kExitSuccess;
}

}  // namespace

Command add_query_command(CLI::App& app) {
  auto options = std::make_shared<QueryOptions>();
  CLI::App* query = app.add_subcommand(
      "query",
      "Ask a scene's world what a ray or a moving ball meets first, or which balls hold a point "
      "or touch a circle or a box (docs/queries.md)");
  query->footer(
      "Examples:\n"
      "  carom query examples/billiards.json --ball 0.635,0.635,0.028575,2,0 --ignore cue\n"
      "  carom query examples/billiards.json --ray 0,0.6,2.54,0 --all --json\n"
      "  carom query examples/box-of-1000.json --time 5 --circle 10,10,2");
  query->add_option("scene", options->scene, "The scene file (- for standard input)")->required();
  query->add_option("--time", options->time, "Run the scene to this scene time first");
  query->add_option("--ray", options->rays, "X,Y,DX,DY: the first ball or wall on the segment");
  query->add_option("--ball", options->casts,
                    "X,Y,R,DX,DY: a ball of radius R moved by (DX, DY): what it touches first");
  query->add_option("--point", options->points, "X,Y: the balls holding the point");
  query->add_option("--circle", options->circles, "X,Y,R: the balls touching the circle");
  query->add_option("--box", options->boxes, "X0,Y0,X1,Y1: the balls touching the box");
  query->add_flag("--all", options->all, "Every hit of each ray, in order, not only the first");
  query->add_option("--ignore", options->ignore, "A ball (name or index) the queries do not see");
  query->add_option("--mask", options->mask, "The filter categories the queries see (bits)");
  query->add_flag("--json", options->json, "One JSON object: the scene, its time, the results");
  return {query, [options] { return run(*options); }};
}

}  // namespace carom::cli
