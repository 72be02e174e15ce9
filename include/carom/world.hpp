// carom: a world of moving balls, static walls and arcs, advanced in exact event order.
//
// Every contact inside a step is found and resolved at the time it really happens, in time order,
// however fast the balls move: the world is event-driven (each ball moves in a straight line
// between its contacts; the user guide: docs/world.md, the design: docs/engine.md). What it
// guarantees:
// - no missed contact: a pair that would touch while approaching is bounced at that time;
// - no overlap beyond rounding: balls never pass through each other or through walls;
// - determinism: the same world and the same calls give bit-identical states and contact lists;
// - exact conservation for elastic contacts, up to the rounding of each bounce.
// Misuse (a stale handle, a bad number, a ball placed overlapping another) throws
// carom::InvalidArgument naming the argument and value. One world per thread: a World shares no
// state with another, so independent worlds may be stepped on different threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "carom/bounce.hpp"
#include "carom/filter.hpp"
#include "carom/handles.hpp"
#include "carom/sensor.hpp"
#include "carom/shapes.hpp"
#include "carom/table.hpp"
#include "carom/vec2.hpp"
#include "carom/wall_motion.hpp"
#include "carom/world_query.hpp"

namespace carom {

enum class Boundary : std::uint8_t {
  open,      // no boundary: balls may travel anywhere
  box,       // four walls along [lower, upper]; no ball ever leaves
  periodic,  // both axes wrap around [lower, upper); walls are refused (see add_segment)
};

struct WorldDef {
  Boundary boundary = Boundary::open;
  Vec2 lower;  // the box or the periodic cell (unused for an open world)
  Vec2 upper;
  double restitution = 1.0;  // for balls whose BallDef leaves it unset
  // Inelastic collapse prevention (the "TC model"): a ball that collided less than this time ago
  // bounces elastically, so that three or more inelastic balls cannot collide infinitely often in
  // finite time. 0 turns it off (on a table, 0 takes Table::contact_time). See docs/engine.md,
  // "Response".
  double collapse_time = 0.0;
  // Side of the broad-phase grid's cells; 0 chooses it (at least the largest diameter; 1.25
  // diameters in a dilute world). A cell smaller than the largest diameter given here is raised
  // to it. Room beyond the diameter is used as the cells' hysteresis (docs/engine.md).
  double cell_size = 0.0;
  // The acceleration of every movable ball (gravity): between its events a ball follows the
  // parabola p + v·t + ½·gravity·t², and every contact time is still exact (docs/world.md,
  // "Gravity"). Immovable balls do not fall. Zero, the default, keeps balls on straight lines;
  // every result is then what it is without the field. Changed between steps by set_gravity.
  Vec2 gravity{};
  // Under gravity, a contact whose bounce would lift a ball less than rest_height of its radius
  // off a support that stands still (a wall, an immovable ball at rest, a resting ball) ends in
  // contact instead: the ball then slides along the support, or rests on it, at no cost in events
  // until something disturbs it (docs/world.md, "Resting and sliding"). > 0; a thousandth of a
  // radius is below what any picture shows. Elastic contacts (restitution 1) bounce however low;
  // only a ball touching a support with no speed to leave it rests.
  double rest_height = 1e-3;
  // Growth (compression): while it is not 0, every movable ball's radius grows as
  // r(t) = r(t₀)·(1 + growth_rate·(t − t₀)), t₀ the time growth was last started or changed, so
  // that size ratios keep (Lubachevsky–Stillinger); immovable balls and walls keep their size.
  // Contacts stay exact (the gaps are quadratics), and a contact's two balls part faster than
  // their radii grow, so growing balls never overlap (docs/world.md, "Growth"). >= 0, finite;
  // 0, the default, keeps radii fixed and every result what it is without the field. Changed
  // between steps by set_growth_rate. Not together with gravity.
  double growth_rate = 0.0;
  // A billiards table (carom/table.hpp; docs/pool.md): the balls slide, roll and spin on a cloth
  // under its friction, meet with throw, and every wall is a cushion. Unset, the default: balls
  // have no spin and every result is what it is without the field. Not together with gravity or
  // growth; moving walls are refused on a table.
  std::optional<Table> table{};
};

struct BallDef {
  Vec2 position;
  Vec2 velocity;
  double radius = 1.0;
  double mass = 1.0;  // > 0, or kImmovable for a ball nothing moves
  // In [0, 1]; unset: the world's. Two balls bounce with the smaller of their two restitutions
  // (a ball of putty does not bounce off a rubber ball); a ball and a wall with the ball's.
  std::optional<double> restitution;
  std::uint64_t user_data = 0;
  // On a table, the ball's angular velocity (carom/table.hpp); without one it must stay zero.
  Spin spin{};
};

enum class ContactKind : std::uint8_t { ball_ball, ball_wall };

// One resolved contact, as the game needs it for sounds, scores and logic.
struct ContactEvent {
  double time = 0.0;  // world time of the contact
  ContactKind kind = ContactKind::ball_ball;
  BallId a;                     // the ball (for two balls, the one with the lower index)
  BallId b;                     // the other ball (ball_ball only)
  WallId wall = 0;              // the wall (ball_wall only)
  Vec2 point;                   // the contact point
  Vec2 normal;                  // unit, from a towards b (or towards the wall)
  double approach_speed = 0.0;  // normal speed at which they met (> 0)
  double impulse = 0.0;         // magnitude of the normal impulse
};

// Why the last step / run_until / run_collisions returned.
enum class StopReason : std::uint8_t {
  none,              // it did what it was asked: reached its time, or resolved `count` contacts
  no_more_contacts,  // run_collisions: no contact will ever happen (see run_collisions)
  time_limit,        // run_collisions(count, time_limit): the limit came before the count
  stop_condition,    // the stop condition answered true
  interrupted,       // request_stop(), or the progress callback answered true
};

// What a run's progress callback is told (see set_progress_callback).
struct RunStatus {
  double time = 0.0;           // the world's time: that of the event processed last
  std::uint64_t events = 0;    // events processed by this run so far (contacts and cell crossings)
  std::uint64_t contacts = 0;  // contacts resolved by this run so far
};

// What set_position does when the new place would overlap a ball or a wall.
enum class Placement : std::uint8_t {
  refuse,        // throw carom::InvalidArgument, leaving the ball where it was
  nearest_free,  // move it along the line from its old place towards the new one, as far as it
                 // can go without overlap (the dragged ball stops where it first touches); in a
                 // periodic world the shortest way to the new place's image in the cell
};

class World {
 public:
  explicit World(const WorldDef& def = {});
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // ---- balls ----
  // Throws if the ball overlaps another ball or a wall, or lies outside a box.
  BallId add_ball(const BallDef& def);
  // The same with the ball's collision filter (carom/filter.hpp): it may be placed overlapping
  // what the filter lets it pass through.
  BallId add_ball(const BallDef& def, const CollisionFilter& filter);
  void remove_ball(BallId id);
  // Makes room for `count` balls in all (live ones and removed ones' reusable handles), so that
  // adding up to that many allocates nothing more: like std::vector::reserve, it spares the
  // copies of the per-ball arrays while they grow, and the peak of memory those copies make.
  // Throws InvalidArgument past the most a world holds (2^30).
  void reserve(std::size_t count);
  [[nodiscard]] bool contains(BallId id) const noexcept;
  // Every live ball, in handle order (BallId::index ascending).
  [[nodiscard]] std::vector<BallId> balls() const;

  // ---- static geometry ----
  // Walls are refused in a periodic world (InvalidArgument): a wall near one edge of the cell
  // touches balls near the opposite edge through the wrap, which needs every wall listed and
  // swept at each of its periodic images (docs/world.md, "Known limits").
  WallId add_segment(const Segment& segment);
  // Consecutive points joined by segments (and the last back to the first when closed); returns
  // the first segment's id, the rest follow in order.
  WallId add_polyline(std::span<const Vec2> points, bool closed = false);
  WallId add_arc(const Arc& arc);
  // Four segments along an axis-aligned box, with consecutive ids from the one returned: bottom
  // (lower-left to lower-right), right, top, left (counter-clockwise).
  WallId add_box(Vec2 lower, Vec2 upper);
  // Sensors (carom/sensor.hpp): a segment, an arc or a disc (a Ball's centre and radius) that
  // balls pass through, recording an enter and an exit at the exact times they start and stop
  // overlapping it (sensor_events()); with SensorAction::remove_ball the ball that enters is
  // removed. Sensors take wall ids (they count in wall_count()) and filters (set_wall_filter);
  // queries do not see them. Refused in a periodic world, as walls are. A ball already
  // overlapping a new sensor enters it at the start of the next run.
  WallId add_sensor(const Segment& segment, SensorAction action = SensorAction::report);
  WallId add_sensor(const Arc& arc, SensorAction action = SensorAction::report);
  WallId add_sensor(const Ball& disc, SensorAction action = SensorAction::report);
  [[nodiscard]] std::size_t wall_count() const noexcept;
  // A wall's shape: a Segment (a box boundary's four walls, ids 0–3, and every segment), an Arc,
  // or a sensor's disc (a Ball); a moving wall's where it is at the world's time. Throws
  // InvalidArgument for an id at or past wall_count().
  [[nodiscard]] std::variant<Segment, Arc, Ball> wall(WallId id) const;
  // What the sensor `id` does; nothing for a wall that is no sensor. Throws InvalidArgument for
  // an id at or past wall_count().
  [[nodiscard]] std::optional<SensorAction> sensor(WallId id) const;
  // The balls inside sensor `id` (overlapping it as of the last enter and exit recorded), in
  // handle order.
  [[nodiscard]] std::vector<BallId> balls_in_sensor(WallId id) const;

  // ---- moving walls (carom/wall_motion.hpp; docs/world.md, "Moving walls") ----
  // Gives a segment or an arc a rigid motion from now, replacing the one it had: it moves so for
  // motion.duration, then stands still where the motion left it. Every ball is predicted again
  // at the next run; under gravity, what rested on the wall falls. A moving wall is met without
  // the grid (each ball's prediction asks about every moving wall: a game has a few). Under
  // gravity a ball cannot rest on a wall while it moves (it hops at its rest speed), and rests
  // on it as on any wall once it stands still. An immovable ball passes through a moving wall.
  // Refused (InvalidArgument) for a sensor, a box boundary's side, a removed wall, and for
  // values that are not finite (the duration may be infinite, not negative).
  void set_wall_motion(WallId wall, const WallMotion& motion);
  // The motion a wall has from now: its pivot where it is now and the duration left; all zero
  // for a wall that stands still.
  [[nodiscard]] WallMotion wall_motion(WallId wall) const;
  // Removes a wall or a sensor: from now on nothing meets it and no query sees it; its id stays
  // taken (wall_count() does not change). What rested on it falls; balls recorded inside a
  // removed sensor leave it without an exit. Refused for a box boundary's side.
  void remove_wall(WallId wall);
  [[nodiscard]] bool wall_removed(WallId wall) const;
  // The definition the world was made with, as given.
  [[nodiscard]] const WorldDef& def() const noexcept;

  // ---- advancing time ----
  // Advances exactly dt (>= 0), resolving every contact in time order; returns the time
  // advanced, less than dt only when the stop condition fired or the run was stopped from
  // outside (stop_reason() says which).
  double step(double dt);
  // Advances to world time `time` (>= time()), or less when stopped early (stop_reason()).
  double run_until(double time);
  // Resolves the next `count` contacts (ball–ball and ball–wall) and stops right after the last;
  // returns how many it resolved: fewer only when no contact will ever happen, the stop
  // condition fired, the run was stopped from outside, or (below) the time limit came first;
  // stop_reason() says which.
  //
  // "No contact will ever happen" is noticed in two ways. No pending event at all (every ball at
  // rest, say): it returns at once. Otherwise, after a stretch of events without a contact (cell
  // crossings: at least 64, and at least 2 per ball, doubling after each failed try) it tries to
  // prove it, and returns when it can, with time() at the last event processed. It can prove it
  // - in an open world or a box: when every pair of balls (one at least movable) is moving apart
  //   or not moving relative to each other, every ball is moving away from every segment's
  //   nearest point, and every ball is outside each arc's full circle by more than its radius
  //   and moving away from its centre (distances to convex sets then grow for ever);
  // - in a periodic world without walls: when every such pair either has no relative velocity
  //   at all, or moves relative to the other along one axis only with the minimum-image gap
  //   across that axis wider than the two radii (plus 10⁻⁹ of the period). So fewer than two
  //   balls, or all at one velocity, always qualify.
  // Other cases cannot be proved in general: two balls in a periodic cell that move relative to
  // each other along a slanted line may meet after an astronomically long time or never (a
  // closed orbit that just misses). There, this call would follow cell crossings for ever: pass
  // a time limit (below) when a run might be of that kind. A contact that will come, but only
  // after an astronomically long flight, is as bad: two balls in an open world moving side by
  // side at speed 7 whose paths converge by 10⁻¹⁵ a time unit meet after 10¹⁶ time units, and the
  // run follows the grid along with them until then.
  std::uint64_t run_collisions(std::uint64_t count);
  // The same, but never past world time `time_limit` (>= time()): when the next contact would
  // come later, it stops there, with the world's time at `time_limit` (as run_until would).
  std::uint64_t run_collisions(std::uint64_t count, double time_limit);

  // Stop early: after each contact the callback is asked, and if it answers true the current
  // step / run ends right after that contact, with every ball brought to that time.
  void set_stop_condition(std::function<bool(const ContactEvent&)> condition);
  // Whether the last run ended because the stop condition fired.
  [[nodiscard]] bool stopped_early() const noexcept;
  // Why the last run returned; none before the first.
  [[nodiscard]] StopReason stop_reason() const noexcept;

  // ---- stopping a run from outside ----
  // Asks the run in progress (or, when none is, the next one) to stop at an event boundary: it
  // returns within kStopCheckEvents events with every ball consistent at the time of the event
  // processed last, stop_reason() == interrupted, and the request cleared. Continuing with the
  // same calls then gives the same states and contacts as a run never stopped. Safe from any
  // thread and from a signal handler: it is one store to a lock-free atomic.
  void request_stop() noexcept;
  // How many events a run processes at most between two looks at a stop request (about a
  // millisecond of work): the callback below is called this often too.
  static constexpr std::uint64_t kStopCheckEvents = 1024;
  // Called at the start of every run and then every kStopCheckEvents events; an answer of true
  // stops the run as request_stop does. For progress reports during long runs with few contacts,
  // and for stop flags of the caller's own (a Ctrl-C handler's). The callback must not change the
  // world. Not saved (a function). Empty: none.
  void set_progress_callback(std::function<bool(const RunStatus&)> callback);

  // Contacts resolved by the last step / run_until / run_collisions, in the order they happened:
  // by time, then kind (ball–ball before ball–wall), then ids. Empty while recording is off.
  [[nodiscard]] std::span<const ContactEvent> contacts() const noexcept;
  // Recording contacts (on by default) keeps every ContactEvent of a run (80 bytes each) until
  // the next; a long science run may turn it off. The stop condition still sees every contact,
  // so a condition that records what it needs and answers false is a per-contact callback.
  void set_contact_recording(bool enabled) noexcept;
  // Sensors' enters and exits during the last step / run_until / run_collisions, in the order
  // they happened (each with its place among contacts()). Always recorded: they are few. A
  // removed ball leaves its sensors without exits.
  [[nodiscard]] std::span<const SensorEvent> sensor_events() const noexcept;
  [[nodiscard]] bool contact_recording() const noexcept;
  // On a table, the balls' changes of motion state during the last run (slide to roll, roll to
  // rest, and those a contact makes), in the order they happened; recorded while contacts are.
  [[nodiscard]] std::span<const MotionEvent> motion_events() const noexcept;

  // ---- queries, at the world's current time ----
  [[nodiscard]] double time() const noexcept;
  [[nodiscard]] Vec2 position(BallId id) const;
  [[nodiscard]] Vec2 velocity(BallId id) const;
  // (Under growth, the radius at the world's time.)
  [[nodiscard]] double radius(BallId id) const;
  [[nodiscard]] double mass(BallId id) const;
  [[nodiscard]] std::uint64_t user_data(BallId id) const;
  [[nodiscard]] std::size_t ball_count() const noexcept;
  [[nodiscard]] double kinetic_energy() const noexcept;  // of movable balls
  // −Σ m·gravity·p over movable balls: the potential energy of gravity, zero at the origin (0
  // without gravity). kinetic_energy() + potential_energy() is the total that elastic contacts
  // keep. In a periodic cell p is the wrapped place, so the total jumps by m·|g·period| as a
  // ball re-enters across the cell's side.
  [[nodiscard]] double potential_energy() const noexcept;
  [[nodiscard]] Vec2 momentum() const noexcept;                  // of movable balls
  [[nodiscard]] std::uint64_t collision_count() const noexcept;  // since creation, all kinds
  // Whether nothing will ever move again by itself: every movable ball still (on a table, every
  // ball stationary, spin included) and no gravity to start one falling.
  [[nodiscard]] bool at_rest() const noexcept;

  // ---- the table (carom/table.hpp; docs/pool.md): refused without WorldDef::table ----
  // A ball's angular velocity at the world's time.
  [[nodiscard]] Spin spin(BallId id) const;
  // A ball's motion state at the world's time (an immovable ball is stationary: friction does
  // not act on what nothing moves).
  [[nodiscard]] MotionState motion_state(BallId id) const;
  // Sets a movable ball's angular velocity from now, keeping its place and velocity.
  void set_spin(BallId id, Spin spin);
  // Strikes a movable ball with the cue: the strike's velocity and spin (those it gives a ball at
  // rest) are added to the ball's.
  void strike(BallId id, const CueStrike& cue);

  // ---- changing the world between steps ----
  // Sets WorldDef::gravity (finite) from the world's time on; every ball keeps its place and
  // velocity at that time.
  void set_gravity(Vec2 gravity);
  // Sets WorldDef::growth_rate (finite, >= 0) from the world's time on: radii grow from what they
  // are now (t₀ becomes now). Throws InvalidArgument for a rate other than 0 while gravity is
  // on (and set_gravity for gravity while a world grows).
  void set_growth_rate(double rate);
  // The growth rate relative to the radii of now that continues the same growth (every radius at
  // the same speed): growth_rate / (1 + growth_rate·(t − t₀)); 0 without growth. A world saved
  // as a scene carries it, with the radii of now.
  [[nodiscard]] double growth_rate_from_now() const noexcept;
  // A thermostat's step: scales every movable ball's velocity about the centre of mass's
  // velocity (momentum kept) so that their kinetic energy relative to it is kT a ball (two
  // degrees of freedom at ½·kT each); returns the work done, the change of kinetic energy.
  // Growth pumps energy into a compression and this takes it out: call it every so often
  // between steps. kT finite and > 0; a world whose balls do not move relative to their centre
  // of mass has nothing to scale (returns 0).
  double set_temperature(double kT);

  // ---- filters (carom/filter.hpp; docs/world.md, "Filters") ----
  // A pair whose filters do not meet passes through each other: no contact, no response, and
  // placing one overlapping the other is allowed. Changing a ball's filter between steps
  // re-predicts that ball (and, through its version, the pending events of balls with it);
  // changing a wall's re-predicts every ball at the next run. Under gravity what rested on the
  // ball or wall falls.
  void set_filter(BallId id, const CollisionFilter& filter);
  [[nodiscard]] CollisionFilter filter(BallId id) const;
  void set_wall_filter(WallId wall, const CollisionFilter& filter);
  [[nodiscard]] CollisionFilter wall_filter(WallId wall) const;

  // ---- changing balls between steps ----
  void set_velocity(BallId id, Vec2 velocity);
  // Returns where the ball ended up (see Placement).
  Vec2 set_position(BallId id, Vec2 position, Placement placement = Placement::refuse);

  // ---- saving and resuming (format: docs/world.md, "Saving and resuming") ----
  // save writes everything that decides the world's future: every slot (live or free) with its
  // generation, local time, motion, user data, (live) radius, mass, restitution and (with
  // collapse_time > 0) last contact time; the free-slot order; walls; the WorldDef; time; collision
  // count; contact recording; the broad-phase grid and every ball's pending predicted event. A
  // world loaded from it and given the same calls as the original gives bit-identical contacts and
  // states (on the same build), whether saved between steps, between run_collisions calls, or
  // after a stop condition ended a run early. Not saved: the stop condition (a function: set it
  // again after load), the last run's contacts() and stopped_early() (results of a call, not
  // state; both start empty/false).
  // The format is versioned binary with a checksum; load throws carom::InvalidArgument saying
  // what is wrong: bad magic, unsupported version, truncated, checksum mismatch, or inconsistent
  // content (naming the field). It checks structure, not physics: audit() after load finds
  // overlaps in a file edited by hand. Streams must be opened in binary mode.
  void save(std::ostream& out) const;
  [[nodiscard]] static World load(std::istream& in);
  // The same through a file. save is write_file_atomically (carom/atomic_file.hpp): a temporary
  // file beside `path` (beside a link's target), synced and renamed onto it, so the file holds the
  // old save or all of the new one, never half. A failure throws InvalidArgument naming `path`.
  void save(const std::filesystem::path& path) const;
  [[nodiscard]] static World load(const std::filesystem::path& path);

  // ---- queries (carom/world_query.hpp; docs/queries.md) ----
  // The world as it stands at time(): each query visits only the grid's cells near what it asks
  // about, so its cost grows with those cells and what is in them, not with the world's size.
  // Touching counts as meeting; results are exact to the rounding of the closed forms the
  // contacts use. Arguments must be finite (radius > 0 for a cast ball, >= 0 for a circle);
  // InvalidArgument otherwise.
  //
  // The first ball or wall the segment from origin to origin + translation meets. A ray that
  // starts inside a ball does not see that ball; walls are met from either side.
  [[nodiscard]] QueryHit cast_ray(Vec2 origin, Vec2 translation,
                                  const QueryFilter& filter = {}) const;
  // Every ball and wall it meets, by fraction (ties: balls before walls, then by handle and wall
  // id), each once (at its first meeting: a long ray in a periodic world meets a ball's copies).
  [[nodiscard]] std::vector<QueryHit> cast_ray_all(Vec2 origin, Vec2 translation,
                                                   const QueryFilter& filter = {}) const;
  // A ball of `radius` at `center` moved by `translation` while the world stands still: the
  // first ball or wall it touches while approaching, as sweep_ball_ball answers for one pair
  // (overlapping what it starts in: fraction 0, `overlapping`; whether approaching or not).
  [[nodiscard]] QueryHit cast_ball(Vec2 center, double radius, Vec2 translation,
                                   const QueryFilter& filter = {}) const;
  // The balls that hold the point (on their edge included), in handle order (that of balls()).
  [[nodiscard]] std::vector<BallId> balls_at_point(Vec2 point,
                                                   const QueryFilter& filter = {}) const;
  // The balls that touch or overlap the circle, in handle order.
  [[nodiscard]] std::vector<BallId> balls_in_circle(Vec2 center, double radius,
                                                    const QueryFilter& filter = {}) const;
  // The balls that touch or overlap the axis-aligned box [lower, upper], in handle order.
  [[nodiscard]] std::vector<BallId> balls_in_box(Vec2 lower, Vec2 upper,
                                                 const QueryFilter& filter = {}) const;

  // ---- checking ----
  // Check of the invariants (no two balls or a ball and a wall overlapping by more than
  // `tolerance` times the sum of radii plus the rounding of their positions, every ball inside a
  // box; two immovable balls may overlap, as they pass through each other); returns a description
  // of the first violation, or nothing. Up to 256 balls it checks every pair (O(N²)); above, it
  // checks each ball's 3×3 block of grid cells (O(N)) after checking that the ball lies in the cell
  // the engine filed it in, the invariant that makes the 3×3 block hold every ball it can touch.
  [[nodiscard]] std::optional<std::string> audit(double tolerance = 1e-9) const;
  // The same, every pair whatever the size: relies on nothing the engine maintains.
  [[nodiscard]] std::optional<std::string> audit_all_pairs(double tolerance = 1e-9) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace carom
