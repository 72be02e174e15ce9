// carom: scenes — a world described as data (JSON), loaded, checked, built and saved.
//
// A Scene is a plain value: the world's settings, explicit balls, static walls (segments,
// polylines, arcs), pockets, and generators that place many balls from a few numbers. It is read
// from and written to JSON (format: docs/scenes.md, schema: docs/scene.schema.json); saving and
// loading round-trip exactly, every double bit for bit. Everything that can be wrong with a scene
// is reported as one carom::SceneError naming the file, line and column, the JSON path of the
// field (balls[3].radius), the value as written and what is wrong with it.
//
// This is the separate library target carom::scene (it links nlohmann_json); the core carom
// library has no dependencies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include "carom/filter.hpp"
#include "carom/sensor.hpp"
#include "carom/shapes.hpp"
#include "carom/table.hpp"
#include "carom/vec2.hpp"
#include "carom/world.hpp"

namespace carom {

// The version written in "carom_scene" and the only one read.
inline constexpr int kSceneFormatVersion = 1;
// The most balls a scene may hold (explicit and generated): a typo with extra zeros is refused at
// once rather than after allocating gigabytes.
inline constexpr std::uint64_t kMaxSceneBalls = 10'000'000;

// Thrown for a scene that cannot be read or built. what() reads
//   FILE:LINE:COLUMN: PATH = VALUE: PROBLEM (did you mean "KEY"?)
// leaving out the parts that do not apply (no file for a string, no location for a problem found
// after loading, no suggestion unless a key is unknown).
class SceneError : public std::runtime_error {
 public:
  struct Details {
    std::string file;        // "" when the scene came from a string with no name
    std::size_t line = 0;    // 1-based; 0 when unknown
    std::size_t column = 0;  // 1-based, in characters (UTF-8 code points); 0 when unknown
    std::string path;        // JSON path of the field: "balls[3].radius"; "" for the whole file
    std::string value;       // the value as written in the file (or as the number reads); may be ""
    std::string problem;     // what is wrong, e.g. "must be > 0"
    std::string suggestion;  // for an unknown key: the nearest known key; otherwise ""
  };

  explicit SceneError(Details details);

  [[nodiscard]] const Details& details() const noexcept { return details_; }

 private:
  Details details_;
};

// Labels only: carom computes in whatever units the numbers are in. Written for the reader and
// for plots. Energy is mass·length²/time², temperature is in energy units (Boltzmann constant 1).
struct SceneUnits {
  std::string length = "m";
  std::string time = "s";
  std::string mass = "kg";
};

struct SceneBall {
  std::optional<std::string> name;  // unique among balls and pockets when given
  Vec2 position;
  Vec2 velocity;
  double radius = 1.0;                // > 0
  double mass = 1.0;                  // > 0, or kImmovable ("mass": "immovable" in JSON)
  std::optional<double> restitution;  // in [0, 1]; unset: the world's
  std::optional<std::string> color;   // any CSS colour text ("#ff8800", "red"); unset: by speed
  CollisionFilter filter;             // which balls and walls it meets ("filter" in JSON)
  Spin spin{};  // angular velocity, on a table only (world.table; carom/table.hpp)
};

struct ScenePolyline {
  std::vector<Vec2> points;  // at least 2
  bool closed = false;       // join the last point back to the first
  CollisionFilter filter;    // of each of its segments ("filter" in JSON)
};

// A pocket: a circle that swallows any ball that touches it. Built as an immovable ball; a ball
// that touches it is removed from the world at that instant (see step_scene). Pockets take no
// part in energy or momentum (they are immovable).
struct ScenePocket {
  std::optional<std::string> name;
  Vec2 position;
  double radius = 1.0;  // > 0
};

// A sensor (World::add_sensor, carom/sensor.hpp): a segment, an arc or a disc that balls pass
// through, each enter and exit recorded; with SensorAction::remove_ball the ball that enters is
// removed. Balls may be placed over it.
struct SceneSensor {
  std::optional<std::string> name;  // unique among balls, pockets and sensors when given
  std::variant<Segment, Arc, Ball> shape;
  SensorAction action = SensorAction::report;
  CollisionFilter filter;  // which balls it sees ("filter" in JSON)
};

enum class GeneratorPlacement : std::uint8_t {
  lattice,  // a triangular lattice spread over the region (periodic if the region is the cell)
  random,   // uniform random positions, each ball tried until it overlaps nothing placed before
};

enum class VelocityDistribution : std::uint8_t {
  fixed,              // every ball gets `velocity`
  uniform_direction,  // speed `speed`, direction uniform on the circle
  maxwell_boltzmann,  // each component normal with variance temperature / mass
};

struct SceneVelocities {
  VelocityDistribution distribution = VelocityDistribution::fixed;
  Vec2 value;                // fixed
  double speed = 1.0;        // uniform_direction, >= 0
  double temperature = 1.0;  // maxwell_boltzmann, >= 0
  // Subtract the mean velocity so the generated balls' total momentum is zero (to rounding).
  bool zero_momentum = false;
};

// N balls of one kind placed by rule. Exactly one of radius and packing_fraction is given: the
// packing fraction φ of the generator's own balls in its region gives r = sqrt(φ·A / (N·π)).
struct SceneGenerator {
  std::optional<std::string> name;  // generated ball i is named NAME#i when given
  GeneratorPlacement placement = GeneratorPlacement::lattice;
  std::uint64_t count = 0;  // >= 1
  std::optional<double> radius;
  std::optional<double> packing_fraction;  // in (0, 1)
  // The axis-aligned region the balls lie inside (whole balls). Unset: the world's box or
  // periodic cell; for a periodic world the balls then fill the cell periodically.
  std::optional<Vec2> region_lower;
  std::optional<Vec2> region_upper;
  double mass = 1.0;  // > 0
  std::optional<double> restitution;
  std::optional<std::string> color;
  SceneVelocities velocities;
  std::uint64_t seed = 1;  // for random placement and random velocities (std::mt19937_64)
};

// A thermostat for runs of the scene (step_scene, run_scene_until, run_scene_collisions): the
// movable balls' velocities are scaled about their centre of mass's so that their kinetic energy
// is `temperature` a ball (World::set_temperature), every `interval` of scene time (at the scene
// clock's multiples of it) or every `collisions` collisions (at the world's collision count's
// multiples of it). Exactly one of the two is set. Growth pumps energy into a compression; this
// takes it out. Steps at fixed multiples make a run resumed from a checkpoint repeat the one never
// stopped.
// A cue strike (World::strike, carom/table.hpp) on a table: the named ball struck when the scene
// clock reads `time`. A ball potted before its shot is not struck.
struct SceneShot {
  std::string ball;   // a movable ball's name
  double time = 0.0;  // scene time, >= the scene's time; shots in order of time
  CueStrike cue;
};

struct SceneThermostat {
  double temperature = 1.0;  // kT, > 0
  std::optional<double> interval;
  std::optional<std::uint64_t> collisions;
};

struct Scene {
  std::string description;  // free text for the reader
  SceneUnits units;
  WorldDef world;     // the world's boundary and settings, as a World is made with
  double time = 0.0;  // the scene's clock at the start (a saved scene continues from it)
  std::vector<SceneBall> balls;
  std::vector<Segment> segments;
  std::vector<ScenePolyline> polylines;
  std::vector<Arc> arcs;
  // The collision filters of the segments and arcs, by index ("filter" in JSON): empty when
  // every one has the default, else one for each.
  std::vector<CollisionFilter> segment_filters;
  std::vector<CollisionFilter> arc_filters;
  // The segments' and arcs' motions, by index ("motion" in JSON; carom/wall_motion.hpp): empty
  // when none moves, else one for each (nothing for one that stands still).
  std::vector<std::optional<WallMotion>> segment_motions;
  std::vector<std::optional<WallMotion>> arc_motions;
  std::vector<ScenePocket> pockets;
  std::vector<SceneSensor> sensors;
  std::vector<SceneGenerator> generators;
  std::optional<SceneThermostat> thermostat;  // none: the runs keep the energy they have
  std::vector<SceneShot> shots;               // on a table: the cue strikes still to come
};

// ---- reading and writing ----

// Parses and checks a scene: the JSON itself, every field (type, finite numbers, ranges, unknown
// keys), and the geometry (no ball overlapping another, a wall or a pocket, every ball inside a
// box, every generator placeable). source_name names the text in messages (a file name or "").
// Throws SceneError.
[[nodiscard]] Scene parse_scene(std::string_view json_text, std::string_view source_name = "");
// Reads the file and parses it (a file that cannot be read is a SceneError too).
[[nodiscard]] Scene load_scene(const std::filesystem::path& path);

// The scene as JSON text (ends with a newline). parse_scene(to_json_text(s)) == s, bit for bit.
[[nodiscard]] std::string to_json_text(const Scene& scene);
// Writes to_json_text(scene) to path atomically (write_file_atomically, carom/atomic_file.hpp):
// the file holds its old content or all of the new one. Throws SceneError if it cannot be written.
void save_scene(const Scene& scene, const std::filesystem::path& path);

// ---- building ----

// Every ball of the scene: the explicit balls, then each generator's balls in generator order.
// Deterministic: the same scene gives the same balls, bit for bit, on the same build.
// Throws SceneError (path generators[i]) when a generator cannot place its balls.
[[nodiscard]] std::vector<SceneBall> expand_balls(const Scene& scene);

// A world built from a scene, and how to find the scene's balls in it.
struct SceneWorld {
  World world;
  Scene scene;  // the scene it was built from, generators expanded into balls
  // balls[i] is scene.balls[i] (null once removed by a pocket or a sensor)
  std::vector<BallId> balls;
  // pockets[k] is scene.pockets[k]: the wall id of a disc sensor that removes the ball entering
  // it (SensorAction::remove_ball), after the scene's sensors the world's last walls.
  std::vector<WallId> pockets;
  std::unordered_map<std::string, BallId> by_name;  // named balls
  double start_time = 0.0;                          // scene time when the world's clock read 0
  double thermostat_work = 0.0;  // Σ of the thermostat's changes of kinetic energy so far
  // sensors[k] is scene.sensors[k]: the world's walls after the scene's own, before the pockets.
  std::vector<WallId> sensors{};
  // The sensors' enters and exits during the last step_scene / run_scene_until /
  // run_scene_collisions, in order (world times; contacts_before is the event's place in the
  // call's `contacts` vector: the index of the contact after it).
  std::vector<SensorEvent> sensor_events{};
  // On a table: the shots struck so far (scene.shots[shots_taken] comes next), and the balls'
  // changes of motion state during the last run call, in order (world times).
  std::size_t shots_taken = 0;
  std::vector<MotionEvent> motion_events{};

  // The scene's clock now: start_time + world.time().
  [[nodiscard]] double time() const noexcept { return start_time + world.time(); }
  // The scene index of a ball id, or nothing (not from this scene).
  [[nodiscard]] std::optional<std::size_t> index_of(BallId id) const;
};

// Builds the world (walls in order: segments, then polylines' segments, then arcs, then sensors,
// then pockets, so wall ids follow the scene). Throws SceneError for a scene the world refuses.
[[nodiscard]] SceneWorld make_world(const Scene& scene);

// A ball that fell into a pocket.
struct PottedBall {
  double time = 0.0;     // scene time
  std::size_t ball = 0;  // scene ball index
  std::size_t pocket = 0;
};

// Like World::step / run_until / run_collisions, with pockets: a ball that touches a pocket is
// removed at that instant (the pocket's sensor removes it; touching a pocket is no contact) and
// the run goes on. Each call appends every contact to contacts and every potting to potted when
// they are given, and the sensors' enters and exits (the pockets' included) to sensor_events.
// Contact times in `contacts` are world times (add start_time for scene time), and so are
// run_scene_until's `time` and run_scene_collisions' `time_limit`. Afterwards
// world.stop_reason() says why the call returned (none, no_more_contacts, time_limit or
// interrupted).
// With a thermostat the runs stop at each of its steps (a multiple of its interval on the scene
// clock, or of its collisions on the world's count, after the call's start), scale the
// velocities, and go on; a step at the call's very end is taken before it returns.
// On a table the runs strike each shot when the scene clock reaches its time (a shot due at the
// call's start is struck first) and go on; run_scene_collisions waits through a world at rest for
// the next shot, and otherwise stops there with no_more_contacts.
double step_scene(SceneWorld& scene_world, double dt, std::vector<ContactEvent>* contacts = nullptr,
                  std::vector<PottedBall>* potted = nullptr);
double run_scene_until(SceneWorld& scene_world, double time,
                       std::vector<ContactEvent>* contacts = nullptr,
                       std::vector<PottedBall>* potted = nullptr);
std::uint64_t run_scene_collisions(SceneWorld& scene_world, std::uint64_t count,
                                   std::vector<ContactEvent>* contacts = nullptr,
                                   std::vector<PottedBall>* potted = nullptr,
                                   double time_limit = std::numeric_limits<double>::infinity());

// The world's wall id of the scene's segment i and arc i (make_world adds walls in the scene's
// order, after a box's four sides).
[[nodiscard]] WallId segment_wall(const SceneWorld& scene_world, std::size_t i);
[[nodiscard]] WallId arc_wall(const SceneWorld& scene_world, std::size_t i);

// The world's state now as a scene to continue from: the same settings (gravity as it is now,
// after any World::set_gravity), walls and pockets, the balls still in the world (positions and
// velocities now, names, colours, restitution kept; on a table spins now and the shots still to
// come), no generators, and time = scene_world.time().
[[nodiscard]] Scene capture_scene(const SceneWorld& scene_world);

// ---- inspecting ----

struct SceneSummary {
  std::size_t balls = 0;  // movable and immovable, pockets excluded
  std::size_t immovable = 0;
  std::size_t walls = 0;  // segments, polyline segments and arcs
  std::size_t pockets = 0;
  std::size_t sensors = 0;
  std::size_t moving_walls = 0;  // segments and arcs given a motion
  double kinetic_energy = 0.0;
  // −Σ m·gravity·p over movable balls, as World::potential_energy (0 without gravity).
  double potential_energy = 0.0;
  Vec2 momentum;
  double ball_area = 0.0;                  // sum of π r² over balls
  std::optional<double> packing_fraction;  // ball_area / area of the box or cell
  // The smallest surface-to-surface distance between two balls (negative: overlap), and which.
  std::optional<double> smallest_gap;
  std::size_t smallest_gap_a = 0;
  std::size_t smallest_gap_b = 0;
};

// Summarises expanded balls (as from expand_balls) in the scene's world. Uses a grid: O(N).
[[nodiscard]] SceneSummary summarize(const Scene& scene, std::span<const SceneBall> balls);

}  // namespace carom
