#include "scene_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include "ball_grid.hpp"
#include "generators.hpp"
#include "scene_geometry.hpp"

namespace carom {
namespace scene_detail {
namespace {

SceneError::Details pathed_details(const JsonPath& where, std::string value, std::string problem) {
  SceneError::Details d;
  d.path = path_text(where);
  d.value = std::move(value);
  d.problem = std::move(problem);
  return d;
}

// Where ball i of the expanded list came from, as a path and a name for messages.
struct BallOrigin {
  JsonPath path;
  std::string label;  // balls[3] "cue", or generators[1] ball 17
};

class Origins {
 public:
  Origins(const Scene& scene, const std::vector<std::size_t>& generator_starts)
      : scene_(scene), starts_(generator_starts) {}

  [[nodiscard]] BallOrigin of(std::size_t i, const std::vector<SceneBall>& balls) const {
    const std::string name = balls[i].name ? " \"" + *balls[i].name + "\"" : std::string();
    if (i < scene_.balls.size()) {
      return {{std::string("balls"), i}, "balls[" + std::to_string(i) + "]" + name};
    }
    std::size_t g = 0;
    while (g + 1 < starts_.size() && starts_[g + 1] <= i) ++g;
    return {{std::string("generators"), g},
            "generators[" + std::to_string(g) + "] ball " + std::to_string(i - starts_[g]) + name};
  }

 private:
  const Scene& scene_;
  const std::vector<std::size_t>& starts_;
};

void check_names(const Scene& scene) {
  std::unordered_map<std::string, JsonPath> seen;
  const auto note = [&](const std::optional<std::string>& name, JsonPath path) {
    if (!name) return;
    const auto [it, added] = seen.emplace(*name, path);
    if (!added) {
      path.emplace_back(std::string("name"));
      throw PathedSceneError(path, "\"" + *name + "\"",
                             "the name is taken already by " + path_text(it->second));
    }
  };
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    note(scene.balls[i].name, {std::string("balls"), i});
  }
  for (std::size_t i = 0; i < scene.pockets.size(); ++i) {
    note(scene.pockets[i].name, {std::string("pockets"), i});
  }
  for (std::size_t i = 0; i < scene.sensors.size(); ++i) {
    note(scene.sensors[i].name, {std::string("sensors"), i});
  }
  // A generator names its balls NAME#0, NAME#1, ...: two generators of one name, or a ball
  // named like one of its balls, would give two balls one name (and a saved scene that does
  // not load).
  std::unordered_map<std::string, std::size_t> generator_of;
  for (std::size_t g = 0; g < scene.generators.size(); ++g) {
    const std::optional<std::string>& name = scene.generators[g].name;
    if (!name) continue;
    const auto [it, added] = generator_of.emplace(*name, g);
    if (!added) {
      throw PathedSceneError(
          {std::string("generators"), g, std::string("name")}, "\"" + *name + "\"",
          "the name is taken already by generators[" + std::to_string(it->second) + "]");
    }
  }
  for (const auto& [name, path] : seen) {
    const std::size_t mark = name.rfind('#');
    if (mark == std::string::npos) continue;
    const auto generator = generator_of.find(name.substr(0, mark));
    if (generator == generator_of.end()) continue;
    const std::string index = name.substr(mark + 1);
    const bool digits =
        !index.empty() && index.size() <= 19 &&
        std::all_of(index.begin(), index.end(), [](char c) { return c >= '0' && c <= '9'; });
    // (Exactly as the generator writes it: no leading zeros.)
    if (!digits || (index.size() > 1 && index[0] == '0')) continue;
    if (std::stoull(index) >= scene.generators[generator->second].count) continue;
    JsonPath where = path;
    where.emplace_back(std::string("name"));
    throw PathedSceneError(where, "\"" + name + "\"",
                           "the name is taken already by generators[" +
                               std::to_string(generator->second) + "]'s ball " + index);
  }
}

// Spins and shots belong to a table; each shot strikes a movable ball of the scene by name, its
// tip on the ball, in order of time from the scene's.
void check_table(const Scene& scene, const std::vector<SceneBall>& balls, const Origins& origins) {
  if (!scene.world.table) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].spin == Spin{}) continue;
      JsonPath where = origins.of(i, balls).path;
      where.emplace_back(std::string("spin"));
      throw PathedSceneError(where,
                             "[" + number_text(balls[i].spin.x) + ", " +
                                 number_text(balls[i].spin.y) + ", " +
                                 number_text(balls[i].spin.z) + "]",
                             "must be [0, 0, 0] without world.table: only balls on a table spin");
    }
    if (!scene.shots.empty()) {
      throw PathedSceneError({std::string("shots")}, "",
                             "needs world.table: a cue strikes balls on a table");
    }
    return;
  }
  std::unordered_map<std::string, std::size_t> by_name;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (balls[i].name) by_name.emplace(*balls[i].name, i);
  }
  double previous = scene.time;
  for (std::size_t k = 0; k < scene.shots.size(); ++k) {
    const SceneShot& shot = scene.shots[k];
    const auto field = [k](const char* key) {
      return JsonPath{std::string("shots"), k, std::string(key)};
    };
    const auto named = by_name.find(shot.ball);
    if (named == by_name.end()) {
      throw PathedSceneError(field("ball"), "\"" + shot.ball + "\"", "names no ball of the scene");
    }
    const SceneBall& ball = balls[named->second];
    if (ball.mass == kImmovable) {
      throw PathedSceneError(field("ball"), "\"" + shot.ball + "\"",
                             "is an immovable ball: a cue cannot move it");
    }
    if (!(shot.cue.side * shot.cue.side + shot.cue.height * shot.cue.height <
          ball.radius * ball.radius)) {
      throw PathedSceneError(field("side"), number_text(shot.cue.side),
                             "must meet the ball: side² + height² must stay below its radius² (" +
                                 number_text(ball.radius) + "²)");
    }
    if (!(shot.time >= previous)) {
      throw PathedSceneError(
          field("time"), number_text(shot.time),
          k == 0 ? "must not come before the scene's time (" + number_text(scene.time) + ")"
                 : "must not come before the shot before it (" + number_text(previous) +
                       "): shots go in order of time");
    }
    previous = shot.time;
  }
}

void check_inside_box(const Scene& scene, const std::vector<SceneBall>& balls,
                      const Origins& origins) {
  if (scene.world.boundary != Boundary::box) return;
  const Vec2 lo = scene.world.lower;
  const Vec2 hi = scene.world.upper;
  const auto outside = [&](Vec2 p, double r) {
    const double slack = kRoundingOverlap * r;
    return p.x - r < lo.x - slack || p.x + r > hi.x + slack || p.y - r < lo.y - slack ||
           p.y + r > hi.y + slack;
  };
  const std::string box = "the box [" + number_text(lo.x) + ", " + number_text(hi.x) + "] x [" +
                          number_text(lo.y) + ", " + number_text(hi.y) + "]";
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (outside(balls[i].position, balls[i].radius)) {
      const BallOrigin o = origins.of(i, balls);
      throw PathedSceneError(o.path, "",
                             o.label + " at (" + number_text(balls[i].position.x) + ", " +
                                 number_text(balls[i].position.y) + ") with radius " +
                                 number_text(balls[i].radius) + " reaches outside " + box);
    }
  }
  for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
    if (outside(scene.pockets[k].position, scene.pockets[k].radius)) {
      throw PathedSceneError({std::string("pockets"), k}, "", "the pocket reaches outside " + box);
    }
  }
}

void check_walls(const Scene& scene, const std::vector<SceneBall>& balls, const Origins& origins) {
  const std::vector<SceneWall> walls = scene_walls(scene);
  if (walls.empty()) return;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (const SceneWall& wall : walls) {
      // A ball passes through a wall whose filter it does not meet.
      if (!should_collide(balls[i].filter, wall.filter)) continue;
      const double gap = distance_to_wall(wall, balls[i].position) - balls[i].radius;
      if (gap < -kRoundingOverlap * balls[i].radius) {
        const BallOrigin o = origins.of(i, balls);
        throw PathedSceneError(o.path, "",
                               o.label + " lies across the wall " + path_text(wall.path) +
                                   ": it overlaps it by " + number_text(-gap));
      }
    }
  }
  for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
    for (const SceneWall& wall : walls) {
      const double gap =
          distance_to_wall(wall, scene.pockets[k].position) - scene.pockets[k].radius;
      if (gap < 0.0) {
        throw PathedSceneError(
            {std::string("pockets"), k}, "",
            "the pocket overlaps the wall " + path_text(wall.path) + " by " + number_text(-gap));
      }
    }
  }
}

void check_overlaps(const Scene& scene, const std::vector<SceneBall>& balls,
                    const Origins& origins) {
  // Pockets are obstacles too, after the balls.
  const std::size_t n = balls.size();
  const std::size_t total = n + scene.pockets.size();
  const auto centre = [&](std::size_t i) {
    return i < n ? balls[i].position : scene.pockets[i - n].position;
  };
  const auto radius = [&](std::size_t i) {
    return i < n ? balls[i].radius : scene.pockets[i - n].radius;
  };
  double largest = 0.0;
  for (std::size_t i = 0; i < total; ++i) largest = std::max(largest, radius(i));
  std::optional<PeriodicCell> cell;
  if (scene.world.boundary == Boundary::periodic) {
    cell = PeriodicCell(scene.world.lower, scene.world.upper);
  }
  BallGrid grid(2.0 * largest, cell);
  const auto label = [&](std::size_t i) {
    return i < n ? origins.of(i, balls).label
                 : "pockets[" + std::to_string(i - n) + "]" +
                       (scene.pockets[i - n].name ? " \"" + *scene.pockets[i - n].name + "\""
                                                  : std::string());
  };
  const auto path = [&](std::size_t i) {
    return i < n ? origins.of(i, balls).path : JsonPath{std::string("pockets"), i - n};
  };
  for (std::size_t i = 0; i < total; ++i) {
    std::optional<std::size_t> hit;
    double overlap = 0.0;
    grid.for_each_near(centre(i), [&](std::size_t j) {
      if (hit) return;
      // Balls whose filters do not meet may overlap (pockets keep the default filter).
      const CollisionFilter none_set;
      if (!should_collide(i < n ? balls[i].filter : none_set, j < n ? balls[j].filter : none_set))
        return;
      const double reach = radius(i) + radius(j);
      const double gap = length(grid.offset(centre(i), centre(j)));
      if (gap < reach * (1.0 - kRoundingOverlap)) {
        hit = j;
        overlap = reach - gap;
      }
    });
    if (hit) {
      throw PathedSceneError(path(i), "",
                             label(i) + " overlaps " + label(*hit) + " by " + number_text(overlap) +
                                 " (radii " + number_text(radius(i)) + " and " +
                                 number_text(radius(*hit)) + ")");
    }
    grid.insert(i, centre(i));
  }
}

std::vector<SceneBall> expand(const Scene& scene, std::vector<std::size_t>* starts) {
  std::vector<SceneBall> balls = scene.balls;
  std::uint64_t total = balls.size();
  for (const SceneGenerator& g : scene.generators) total += g.count;
  if (total > kMaxSceneBalls) {
    throw PathedSceneError({std::string("generators")}, "",
                           "the scene would hold " + std::to_string(total) + " balls, more than " +
                               std::to_string(kMaxSceneBalls));
  }
  for (std::size_t i = 0; i < scene.generators.size(); ++i) {
    if (starts != nullptr) starts->push_back(balls.size());
    std::vector<SceneBall> generated = generate_balls(scene, i, balls);
    balls.insert(balls.end(), generated.begin(), generated.end());
  }
  return balls;
}

}  // namespace

PathedSceneError::PathedSceneError(JsonPath where, std::string value, std::string problem)
    : SceneError(pathed_details(where, std::move(value), std::move(problem))),
      where_(std::move(where)) {}

std::vector<SceneBall> check_scene(const Scene& scene) {
  check_names(scene);
  std::vector<std::size_t> starts;
  std::vector<SceneBall> balls = expand(scene, &starts);
  const Origins origins(scene, starts);
  check_inside_box(scene, balls, origins);
  check_walls(scene, balls, origins);
  check_overlaps(scene, balls, origins);
  check_table(scene, balls, origins);
  return balls;
}

void separate_touching(const Scene& scene, std::vector<SceneBall>& balls) {
  if (balls.empty()) return;
  const std::vector<SceneWall> walls = scene_walls(scene);
  double largest = 0.0;
  for (const SceneBall& b : balls) largest = std::max(largest, b.radius);
  for (const ScenePocket& p : scene.pockets) largest = std::max(largest, p.radius);
  std::optional<PeriodicCell> cell;
  if (scene.world.boundary == Boundary::periodic) {
    cell = PeriodicCell(scene.world.lower, scene.world.upper);
  }
  // Moving a ball out by twice its overlap (plus a few ulps of the reach) leaves it clear of the
  // one it touched whatever the rounding of the move itself.
  constexpr double kUlps = 8.0 * std::numeric_limits<double>::epsilon();
  const Vec2 lower = scene.world.lower;
  const Vec2 upper = scene.world.upper;
  const std::array<Segment, 4> box_sides{
      Segment{lower, {upper.x, lower.y}}, Segment{{upper.x, lower.y}, upper},
      Segment{upper, {lower.x, upper.y}}, Segment{{lower.x, upper.y}, lower}};
  const auto push = [&](SceneBall& ball, Vec2 away, double overlap, double reach) {
    const Vec2 direction = normalized(away);
    if (direction == Vec2{}) return;
    ball.position += direction * (2.0 * std::max(overlap, 0.0) + kUlps * reach);
  };
  // A push can move a ball onto another one or into a wall (in a settled pile every ball
  // touches several): passes repeat, with the world's own test of an overlap, until none is
  // left. The first pass also pushes exact touches, as the world's contacts need a gap.
  constexpr int kPasses = 64;
  for (int pass = 0; pass < kPasses; ++pass) {
    const bool first = pass == 0;
    const auto overlapping = [&](Vec2 away, double reach) {
      return first ? reach - length(away) >= 0.0 : length_squared(away) < reach * reach;
    };
    // Clear of the box and the walls; whether the ball moved.
    const auto clear_of_walls = [&](SceneBall& ball) {
      const Vec2 before = ball.position;
      if (scene.world.boundary == Boundary::box) {
        const double r = ball.radius;
        const Vec2 lo = scene.world.lower + Vec2{r, r};
        const Vec2 hi = scene.world.upper - Vec2{r, r};
        ball.position.x = std::clamp(ball.position.x, lo.x, hi.x);
        ball.position.y = std::clamp(ball.position.y, lo.y, hi.y);
        // (The world takes the box's sides for walls, with its own test of a touch, which a
        // ball clamped to the side can fail by a rounding.)
        for (const Segment& side : box_sides) {
          const Vec2 away = ball.position - carom::nearest_point(side, ball.position);
          if (!first && overlapping(away, r)) push(ball, away, r - length(away), r);
        }
      }
      for (const SceneWall& wall : walls) {
        const Vec2 nearest = std::visit(
            [&](const auto& shape) { return carom::nearest_point(shape, ball.position); },
            wall.shape);
        const Vec2 away = ball.position - nearest;
        if (overlapping(away, ball.radius))
          push(ball, away, ball.radius - length(away), ball.radius);
      }
      return ball.position != before;
    };
    bool pushed = false;
    for (SceneBall& ball : balls) pushed = clear_of_walls(ball) || pushed;
    BallGrid grid(2.0 * largest, cell);
    std::vector<Vec2> centres;
    std::vector<double> radii;
    const std::size_t pockets = scene.pockets.size();
    for (const ScenePocket& p : scene.pockets) {
      grid.insert(centres.size(), p.position);
      centres.push_back(p.position);
      radii.push_back(p.radius);
    }
    for (SceneBall& ball : balls) {
      grid.for_each_near(ball.position, [&](std::size_t j) {
        const Vec2 away = grid.offset(centres[j], ball.position);
        const double reach = ball.radius + radii[j];
        if (!overlapping(away, reach)) return;
        pushed = true;
        if (pass == 0 || j < pockets) {
          push(ball, away, reach - length(away), reach);
          return;
        }
        // Later passes part both balls, each by the overlap: pushing only the later one can
        // press it back into what it pushed before (a ball between a floor and one above it).
        SceneBall& other = balls[j - pockets];
        const double overlap = 0.5 * (reach - length(away));
        push(ball, away, overlap, reach);
        push(other, -away, overlap, reach);
        centres[j] = other.position;
      });
      grid.insert(centres.size(), ball.position);
      centres.push_back(ball.position);
      radii.push_back(ball.radius);
    }
    if (!pushed) return;
  }
}

}  // namespace scene_detail

std::vector<SceneBall> expand_balls(const Scene& scene) {
  return scene_detail::expand(scene, nullptr);
}

}  // namespace carom
