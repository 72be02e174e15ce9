// carom internal: the state behind carom::World and the event-driven engine's operations.
// The engine itself is in parts: world_run.cpp (the event loop), world_response.cpp,
// world_prediction.cpp with prediction_steps.hpp, world_cell_crossing.cpp, world_grid_upkeep.cpp;
// the public API with its validation in world.cpp. Design: docs/engine.md.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "ball_slot.hpp"
#include "ball_store.hpp"
#include "carom/bounce.hpp"  // kImmovable
#include "carom/geometry.hpp"
#include "carom/sweep.hpp"  // Motion
#include "carom/world.hpp"
#include "carriage.hpp"
#include "core/accelerated_sweep.hpp"
#include "event_queue.hpp"
#include "filter_table.hpp"
#include "grid.hpp"
#include "huge_page_allocator.hpp"
#include "lookahead.hpp"
#include "pair_batch.hpp"
#include "save_format.hpp"
#include "species.hpp"
#include "table_slot.hpp"
#include "wall.hpp"

namespace carom {

namespace detail {

// Grid cells are this much wider than the largest diameter: a ball is filed in a cell by its
// crossing events, and at the moment it changes cells its computed centre may sit a rounding on
// the old side. The margin keeps every ball that can touch it within the 3×3 block regardless.
inline constexpr double kCellMargin = 1e-6;
// A grid's hysteresis (grid.hpp) is at most this fraction of its cell: a periodic pair's offset
// then moves by under 2.4 cells between its prediction and its contact, so it was under 3.4 when
// predicted, below half a period from kSingleImageMinCells (7) cells on (docs/engine.md,
// "Boundaries"). Dilute cells have just under it; larger ones meet it.
inline constexpr double kMostHysteresis = 0.1;

// set_position(nearest_free)'s sweep: whether the ball touched something on its way, where it
// then stops, and where the sweep itself put its centre at that touch.
struct DragStop {
  bool touched = false;
  Vec2 stop;
  Vec2 swept;
};

}  // namespace detail

// The state of a world: its balls (the store it is: slots, handles, generations, the free
// handles), its walls, grid, queue and settings.
struct World::Impl : detail::BallStore {
  Impl() { grid.use_slots(balls); }
  Impl(const Impl&) = delete;  // the grid names `balls` by address
  Impl& operator=(const Impl&) = delete;
  Impl(Impl&&) = delete;
  Impl& operator=(Impl&&) = delete;
  ~Impl() = default;

  WorldDef def;
  detail::SpeciesTable species;
  detail::FilterTable filters;  // the balls' (BallInfo::filter) and walls' (Wall::filter)
  // By slot, the time of each ball's latest contact: read only by inelastic collapse prevention,
  // so kept (and sized) only when def.collapse_time > 0, saving 8 bytes a ball otherwise.
  std::vector<double> last_contact_times;
  std::vector<detail::Wall> walls;
  std::vector<std::uint32_t> moving_walls;  // the ids of the walls with a path, ascending
  std::uint32_t boundary_walls = 0;         // the box boundary's four walls come first
  PeriodicCell periodic_cell;               // the boundary of a periodic world
  double largest_radius = 0.0;  // of every ball ever added (never lowered: cells stay valid)

  detail::Grid grid;
  // Prediction's batch of pairs (predict_named), kept here rather than on the stack: its 2.4 KB
  // stay in the cache between predictions, and predict's frame needs no realignment to 64 bytes
  // (75 instructions a collision fewer).
  detail::PairBatch pair_batch;
  detail::EventQueue queue;
  detail::Lookahead lookahead;  // large worlds' prefetching of the events ahead

  double time = 0.0;
  std::uint64_t collisions = 0;
  std::uint64_t events_since_sort = 0;
  std::vector<ContactEvent> contacts;
  std::vector<SensorEvent> sensor_events;  // of the last run
  // The (ball, sensor) pairs overlapping as last recorded: handle index << 32 | wall id, so that
  // iteration (and the save) goes by handle.
  std::set<std::uint64_t> sensor_inside;
  ContactEvent last_contact;  // the latest resolved, recorded or not (for the stop condition)
  std::function<bool(const ContactEvent&)> stop_condition;
  std::function<bool(const RunStatus&)> progress_callback;
  // Set by request_stop from any thread or a signal handler; cleared by the run that stops.
  std::atomic<bool> stop_requested{false};
  static_assert(std::atomic<bool>::is_always_lock_free, "request_stop must be signal-safe");
  StopReason stop_reason = StopReason::none;

  // The flags together, so that they pad the structure once.
  bool grid_valid = false;
  bool events_valid = false;
  bool record_contacts = true;
  // Whether some ball's restitution differs from def.restitution; until then contacts need not
  // read the balls' infos (a cache miss each in a large world).
  bool mixed_restitution = false;
  // Whether a moving immovable ball or a moving wall has met a ball in this run: a run that
  // would never end is then refused as a crush.
  bool mover_met = false;
  // Whether def.gravity is not zero: only then do the parts for accelerated motion run, so that a
  // world without gravity takes exactly the paths it always took.
  bool gravity_on = false;
  // Whether def.growth_rate is not zero (balls grow: world_growth.cpp).
  bool growth_on = false;
  // Whether def.table is set (balls slide, roll and spin on a cloth: world_table.cpp).
  bool table_on = false;
  // Whether balls move with accelerations (gravity, or a table's friction): only then do their
  // places and velocities follow parabolas.
  bool accelerated = false;
  // Whether a law beyond straight lines at fixed radii moves the balls (gravity, growth or a
  // table): only then does the general prediction (world_gravity.cpp) run.
  bool general_motion = false;
  // Under growth: the time from which radii grow (the species' radii are those at it), the rate
  // relative to those radii (def.growth_rate relative to the radii when it was set: the two
  // differ once radii have been brought to a later time, which keeps each radius's growth speed),
  // and the time at which the largest ball outgrows the grid's cells (then re-planned).
  double growth_start = 0.0;
  double growth_relative = 0.0;
  double growth_regrid_time = std::numeric_limits<double>::infinity();
  // By slot, how gravity carries each ball (carriage.hpp): sized with the slots while gravity is
  // on, empty otherwise.
  std::vector<detail::Carriage> carriages;
  // On a table: the cloth, the cushions and the balls' friction from def.table; by slot, each
  // ball's spin and motion state (sized with the slots); the state changes of the last run.
  detail::Cloth cloth;
  detail::Cushion cushion;
  std::vector<detail::TableSlot> table_slots;
  std::vector<MotionEvent> motion_events;
  // (jammed) The instant of the latest slow contact, the handles of the balls in slow contacts
  // at it, and how many jams at it let a ball slide on along its support rather than rest.
  double jam_time = -std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> jam_balls;
  std::size_t jam_slides = 0;

  // ---- handles ----
  // The slot of the live ball `id` names; throws InvalidArgument (naming `function`) for a null
  // or stale handle.
  [[nodiscard]] std::uint32_t slot_of(const char* function, BallId id) const;

  // ---- geometry ----
  [[nodiscard]] const detail::Species& species_of(std::uint32_t ball) const {
    return species[balls[ball].species];
  }
  [[nodiscard]] double radius_of(std::uint32_t ball) const { return species_of(ball).radius; }
  // Under growth a movable ball's radius at t (radius_of is its radius at growth_start), and how
  // fast it grows; otherwise radius_of and 0.
  [[nodiscard]] double radius_at(std::uint32_t ball, double t) const {
    if (!growth_on || !movable(ball)) return radius_of(ball);
    return radius_of(ball) * (1.0 + growth_relative * (t - growth_start));
  }
  [[nodiscard]] double growth_of(std::uint32_t ball) const {
    return growth_on && movable(ball) ? radius_of(ball) * growth_relative : 0.0;
  }
  [[nodiscard]] bool movable(std::uint32_t ball) const { return species_of(ball).movable(); }
  // A ball's place and velocity at t (at or after its local time): on its straight line, or
  // under gravity on its parabola.
  [[nodiscard]] Vec2 position_at(std::uint32_t ball, double t) const {
    if (accelerated) [[unlikely]] {
      const detail::BallSlot& b = balls[ball];
      const double dt = t - b.local_time;
      const Vec2 a = acceleration_of(ball);
      // (The core's position_at is the same sum, with care where it overflows.)
      const Vec2 at = b.position + b.velocity * dt + (a * (0.5 * dt)) * dt;
      return is_finite(at) ? at : detail::position_at(b.position, {b.velocity, a}, dt);
    }
    return balls[ball].position_at(t);
  }
  [[nodiscard]] Vec2 velocity_at(std::uint32_t ball, double t) const {
    const detail::BallSlot& b = balls[ball];
    if (accelerated) [[unlikely]]
      return b.velocity + acceleration_of(ball) * (t - b.local_time);
    return b.velocity;
  }
  // The acceleration a ball moves with: gravity for a movable ball, or its part along a support
  // the ball slides on, or none for a ball at rest (docs/world.md, "Gravity"); on a table, the
  // cloth's friction in the ball's state.
  [[nodiscard]] Vec2 acceleration_of(std::uint32_t ball) const {
    if (table_on) return table_slots[ball].acceleration;
    return gravity_on && movable(ball) ? carriages[ball].acceleration : Vec2{};
  }
  [[nodiscard]] Motion motion_of(std::uint32_t ball) const {
    return {balls[ball].velocity, acceleration_of(ball), growth_of(ball)};
  }
  // The shortest of the periodic images of d (d itself in a world that does not wrap).
  [[nodiscard]] Vec2 minimum_image(Vec2 d) const {
    return def.boundary == Boundary::periodic ? periodic_cell.minimum_image(d) : d;
  }
  [[nodiscard]] Vec2 wrap_into_cell(Vec2 p) const {
    return def.boundary == Boundary::periodic ? periodic_cell.wrap(p) : p;
  }
  // nearest_free's sweep of ball `slot` from `from` to `end` (world.cpp).
  [[nodiscard]] detail::DragStop sweep_drag(std::uint32_t slot, Vec2 from, Vec2 end) const;
  // The balls a drag from a to b might touch, from the grid (world.cpp); nothing where a scan of
  // every ball is cheaper.
  [[nodiscard]] std::optional<std::vector<std::uint32_t>> balls_near_path(Vec2 a, Vec2 b,
                                                                          double reach) const;
  // The first ball or wall that a ball of radius r at p would overlap (ignoring `except`), as a
  // message; empty when the place is free.
  [[nodiscard]] std::string overlap_at(Vec2 p, double r, std::uint32_t except,
                                       std::uint32_t filter = 0) const;
  // Whether two balls, or a ball and a wall, meet under their filters (always, in a world that
  // never set one).
  [[nodiscard]] bool balls_meet(std::uint32_t a, std::uint32_t b) const {
    return !filters.active() || filters.meet(infos[a].filter, infos[b].filter);
  }
  [[nodiscard]] bool meets_wall(std::uint32_t ball, std::uint32_t wall) const {
    return !filters.active() || filter_meets_wall(infos[ball].filter, wall);
  }
  // Keeps in `best` the earlier of it and ball's contact of `kind` with `partner` at t from now,
  // unless their filters let them through: how the general predictions (gravity, growth) take a
  // contact.
  void consider_event(detail::Event& best, std::uint32_t ball, double t, detail::EventKind kind,
                      std::uint32_t partner, std::uint32_t partner_version) const {
    if (kind == detail::EventKind::ball_ball ? !balls_meet(ball, partner)
                                             : !meets_wall(ball, partner)) {
      return;
    }
    detail::Event candidate;
    candidate.time = time + t;
    candidate.kind = kind;
    candidate.owner = ball;
    candidate.partner = partner;
    candidate.partner_version = partner_version;
    if (detail::earlier(candidate, best, handle_of.data())) best = candidate;
  }
  // ---- sensors (world_sensors.cpp) ----
  [[nodiscard]] std::uint64_t sensor_key(std::uint32_t ball, std::uint32_t wall) const {
    return std::uint64_t{handle_of[ball]} << 32 | wall;
  }
  // Keeps in `best` the earlier of it and the ball's next enter or exit at sensor `wall`, the
  // ball (of that shape, at the world's time) moving with `motion`: an enter only where the
  // filters meet, an exit wherever it is recorded inside.
  void consider_sensor(detail::Event& best, std::uint32_t ball, std::uint32_t wall,
                       const Ball& shape, const Motion& motion, double horizon) const;
  // consider_sensor for every sensor the ball is recorded inside, listed in its cell or not (it
  // was placed far from it, say): its exit is due.
  void consider_inside_sensors(detail::Event& best, std::uint32_t ball, const Ball& shape,
                               const Motion& motion, double horizon) const;
  // A ball's enter or exit at a sensor at t: recorded, and the ball removed (a pocket) or
  // predicted again. Never a contact.
  bool process_sensor(std::uint32_t ball, std::uint32_t wall, double t);
  // ---- moving walls (world_moving_walls.cpp) ----
  // Whether a ball rests or slides on a wall (under gravity).
  [[nodiscard]] bool rests_on(std::uint32_t ball, std::uint32_t wall) const;
  // Keeps in `best` the earlier of it and the ball's next event with each moving wall within
  // `horizon`: a contact, or a time to look again.
  void consider_moving_walls(detail::Event& best, std::uint32_t ball, const Ball& shape,
                             const Motion& motion, double horizon) const;
  // A ball_wall event of a moving wall.
  bool process_moving_wall(const detail::Event& event);
  // Brings every moving wall's shape to the world's time (for the queries, the audit, wall()).
  void place_moving_walls();
  // The wall `id` that a change between runs (set_wall_motion, remove_wall) may be made to: not a
  // side of the box boundary, not removed; refused (naming `function`) otherwise.
  detail::Wall& changeable_wall(const char* function, std::uint32_t id);
  // Under gravity, the balls resting or sliding on wall `id` fall (it changes).
  void free_resting_on(std::uint32_t id);
  // Adds a wall or a sensor (validated) and lists it; its id.
  WallId add_wall(const char* function, const char* argument, const detail::Wall& wall);
  // Forgets the sensor pairs of a ball that is gone.
  void forget_sensor_pairs(std::uint32_t handle);
  // Removes a live ball, during a run or between runs (whatever it carried falls).
  void remove_slot(std::uint32_t slot);

  // A box boundary's sides (walls 0 to 3) meet every ball, whatever its filter: no ball leaves.
  [[nodiscard]] bool filter_meets_wall(std::uint32_t filter, std::uint32_t wall) const {
    return (def.boundary == Boundary::box && wall < 4) || filters.meet(filter, walls[wall].filter);
  }

  // ---- audit (world_audit.cpp): a description of the first violation found, or nothing ----
  [[nodiscard]] std::optional<std::string> audit_all_pairs(double tolerance) const;
  [[nodiscard]] std::optional<std::string> audit_with_grid(double tolerance) const;
  [[nodiscard]] std::optional<std::string> audit_ball(std::uint32_t i, Vec2 p,
                                                      double tolerance) const;
  [[nodiscard]] std::optional<std::string> audit_wall(std::uint32_t i, Vec2 p, std::uint32_t k,
                                                      double tolerance) const;
  [[nodiscard]] std::optional<std::string> audit_pair(std::uint32_t i, Vec2 p, std::uint32_t j,
                                                      double tolerance) const;

  // Whether anyone reads a contact's details: the contact list or the stop condition.
  [[nodiscard]] bool contact_wanted() const { return record_contacts || bool(stop_condition); }
  [[nodiscard]] double restitution_of(std::uint32_t ball) const {
    return mixed_restitution ? species_of(ball).restitution : def.restitution;
  }
  void record(const ContactEvent& contact) {
    last_contact = contact;
    if (record_contacts) contacts.push_back(contact);
  }

  // ---- save and resume (world_save.cpp) ----
  [[nodiscard]] std::string save_payload() const;
  // The version of the save format this world is written in: with gravity 3, with growth 4, else
  // 2 (world_save.cpp).
  [[nodiscard]] std::uint32_t save_version() const;
  // Fills a freshly constructed world from a payload whose checksum matched, checking that its
  // content is consistent.
  void load_payload(detail::ByteReader& in, std::uint32_t version);
  void load_grid(detail::ByteReader& in);
  void load_carriage(detail::ByteReader& in, std::uint32_t slot, const std::string& which);
  void load_filters(detail::ByteReader& in);
  void load_sensors(detail::ByteReader& in);
  void load_wall_changes(detail::ByteReader& in);
  void save_table(detail::ByteWriter& out) const;
  void load_table(detail::ByteReader& in);
  [[nodiscard]] bool has_wall_changes() const {
    return std::any_of(walls.begin(), walls.end(),
                       [](const detail::Wall& wall) { return wall.moving || wall.removed; });
  }
  [[nodiscard]] bool has_sensors() const {
    return std::any_of(walls.begin(), walls.end(), [](const detail::Wall& wall) {
      return wall.sensor != detail::SensorRole::none;
    });
  }

  // ---- the grid's upkeep (world_grid_upkeep.cpp) ----
  // Makes the grid hold every live ball with cells no smaller than the largest diameter (and,
  // for an open world, cover every ball and wall), rebuilding it when it does not.
  void ensure_grid(Vec2 extra_point, double extra_radius);
  void rebuild_grid(Vec2 extra_point, double extra_radius);
  // Lists every wall in the grid's cells.
  void list_walls();
  // After a wall is added between runs (the last of `walls`): lists it and re-predicts the balls
  // that could meet it, or leaves a re-plan of the grid and every prediction to the next run when
  // the grid does not cover it.
  void wall_added();
  [[nodiscard]] bool grid_too_coarse(std::size_t ball_total, double coarseness) const;
  // The side of a cell for `ball_total` balls over that extent whose largest radius is
  // `largest`, before rounding the cell count.
  [[nodiscard]] double wanted_cell_size(double extent_x, double extent_y, std::size_t ball_total,
                                        double largest) const;
  // Renumbers the slots cell by cell (docs/engine.md, "Memory"); changes no result.
  void sort_by_cell();

  // ---- prediction (world_prediction.cpp, prediction_steps.hpp) ----
  void predict_all();
  // After a change to one ball between runs (its place or course, or its removal): predicts that
  // ball alone, when every other ball's pending event is still valid, rather than every ball at
  // the next run (docs/world.md, "Changing balls between steps").
  void repredict_changed(std::uint32_t ball);
  void predict(std::uint32_t ball);
  // predict for a world with gravity (world_gravity.cpp): every pair and wall by the
  // accelerated queries, the cell's exit by a quadratic, leaving a support by a quadratic.
  void predict_under_gravity(std::uint32_t ball);
  // predict for a world with growth (world_growth_prediction.cpp): each pair by the pair
  // equation's closed form where it is clear of its rounding, else by the certified isolation.
  // `crossed`: the side of its old cell a crossing took the ball through, where its last
  // prediction met no ball (only the three cells the crossing brings into reach are looked at),
  // or kWholeBlock.
  static constexpr std::uint32_t kWholeBlock = 4;
  void predict_growing(std::uint32_t ball, std::uint32_t crossed = kWholeBlock);

  // ---- growth (world_growth.cpp; docs/engine.md, "Growth") ----
  // Radii as they are now become the species' radii, and t₀ now: before the rate changes, and
  // before a ball is added, so that the formula holds from one t₀.
  void settle_growth();
  // When the largest movable ball outgrows the cells: the time re-planning is due.
  void plan_growth_regrid();
  // The grid re-planned at its due time t (every ball brought to t, radii settled, predictions
  // renewed), with room for the balls to grow into.
  void regrid_for_growth(double t);
  bool resolve_pair_under_growth(std::uint32_t i, std::uint32_t j, double t);
  bool resolve_wall_under_growth(std::uint32_t i, std::uint32_t wall, double t);

  // ---- the table (world_table.cpp; docs/engine.md, "The table") ----
  // Sets def.table's derived state (the cloth, the cushions) and sizes the table slots.
  void use_table();
  // A ball's state on the table at its local time.
  [[nodiscard]] detail::TableBall table_ball(std::uint32_t ball) const;
  // Gives a ball at its local time t the velocity and spin of `state` and the motion state they
  // make (an immovable ball stays stationary), recording a change of state where `record` (in a
  // run) and contacts are recorded.
  void set_on_table(std::uint32_t ball, const detail::TableBall& state, double t,
                    bool record = true);
  // advance's part on a table: the spin follows the state.
  void advance_on_table(std::uint32_t ball, double t);
  // A ball's motion state ends at its event: it begins the next.
  void process_motion_change(const detail::Event& event);
  bool resolve_pair_on_table(std::uint32_t i, std::uint32_t j, double t);
  bool resolve_wall_on_table(std::uint32_t i, std::uint32_t wall, double t);
  // The refusal of a table call (naming `function`) in a world without a table.
  void require_table(const char* function) const;

  // ---- resting and sliding under gravity (world_resting.cpp; docs/engine.md, "Resting and
  // sliding") ----
  // A free ball's carriage under the current gravity.
  [[nodiscard]] detail::Carriage free_carriage() const;
  // Every ball free (gravity turned on or changed), or no carriages at all (turned off).
  void reset_carriages();
  // The normal speed below which a contact of this ball with a support ends in contact rather
  // than a bounce: √(2·|g|·rest_height·radius), the speed that lifts it rest_height radii.
  [[nodiscard]] double rest_speed(std::uint32_t ball) const;
  // Whether a ball can carry others: it stands still (immovable and still, or resting).
  [[nodiscard]] bool can_carry(std::uint32_t ball) const;
  // A ball whose course something changed: free, and every ball it carried freed too (their
  // predictions renewed), recursively.
  void disturb(std::uint32_t ball);
  // disturb's second half: frees the balls a ball carried (and those they carried).
  void wake_carried(std::uint32_t ball);
  // A ball whose normal velocity towards a static support (`support`, at unit `normal` from its
  // centre) is gone: sliding on it, or resting on it and the support it already had.
  void settle(std::uint32_t ball, std::uint32_t support, Vec2 normal,
              const detail::Carriage& before);
  // A ball sliding on a support that gravity presses against a free ball: pushes it along (both
  // then move with the contact forces that keep the three touching), where those forces push.
  bool push_along(std::uint32_t slider, std::uint32_t pushed, Vec2 normal);
  // A slow contact, at a jam, of a ball sliding down a sloping wall (`normal` from it to
  // `other`) with a free ball that presses it into that wall, or with a ball sliding on the same
  // segment (a free one that touches that segment slides on it first): the one impulse that
  // leaves them on their lines and without approach, the wall bearing its part. False where
  // neither is so (changing nothing but such a landing on the segment).
  bool meet_on_support(std::uint32_t slider, std::uint32_t other, Vec2 normal);
  // Two balls pressed together that neither can carry: both rest, each on the other (and on its
  // own support); false, changing nothing, where `only_slow` and either is faster than its rest
  // speed.
  bool hold_each_other(std::uint32_t i, std::uint32_t j, bool only_slow);
  // A jam of free balls in flight: i, j and the free balls touching them, transitively, move on
  // at their centre of mass's velocity. False (and nothing changed) where one of them touches a
  // ball that is not free, so that the jam stands on something.
  bool move_together(std::uint32_t i, std::uint32_t j, double t);
  // Whether every support a carried ball lists can still carry it.
  [[nodiscard]] bool supports_hold(std::uint32_t ball) const;
  // Counts a slow contact of balls i and j (j = i: of i with a wall) at t: true when an
  // inelastic one meets a ball already in a slow contact at this instant (a press handed back
  // and forth), or when there have been too many at one instant.
  bool jammed(double t, std::uint32_t i, std::uint32_t j, bool inelastic);
  // An event under gravity or growth: each contact by its law's resolve.
  bool process_general(const detail::Event& event);
  // A ball's contact with a wall confirmed at t (the ball brought to t) under gravity or
  // growth: the query's contact now, or one a sliver ahead that the motion or the clock cannot
  // reach; with the touched point and the normal (towards the wall) either way.
  struct WallTouch {
    Impact now;
    Vec2 point;
    Vec2 normal;
  };
  [[nodiscard]] WallTouch touch_wall(std::uint32_t ball, std::uint32_t wall, double t) const;
  bool resolve_pair_under_gravity(std::uint32_t i, std::uint32_t j, double t);
  bool resolve_wall_under_gravity(std::uint32_t i, std::uint32_t wall, double t);
  // predict for a contact's two balls, i's slot set first (world_prediction.cpp).
  void predict_both(std::uint32_t i, std::uint32_t j);
  // predict's two parts (prediction_steps.hpp): the cell's exit and walls, then the balls around.
  struct PredictionCell {
    std::int32_t cell;
    std::int32_t cx;
    std::int32_t cy;
    bool interior;  // away from the grid's edges: no minimum image needed
  };
  bool start_prediction(std::uint32_t ball, detail::Event& best, detail::SlotQuery& query,
                        PredictionCell& where) const;
  void finish_prediction(bool named, detail::Event& best, const detail::SlotQuery& query,
                         const PredictionCell& where);
  // predict's contacts with the balls around (prediction_steps.hpp): read from their slots by the
  // pair kernel (a movable ball in an interior cell), or gathered (every case).
  // (These three return whether some pair meets, at any time.)
  bool predict_named(const detail::SlotQuery& query, std::int32_t cx, std::int32_t cy,
                     detail::Event& best);
  bool solve_named(const detail::SlotQuery& query, std::size_t& count, detail::Event& best);
  bool take_hits(std::uint32_t hits, std::uint32_t rescales, const detail::SlotQuery& query,
                 detail::Event& best) const;
  bool predict_gathered(std::uint32_t ball, std::int32_t cell, bool interior,
                        detail::Event& best) const;
  void file_prediction(detail::Event& best, bool found);
  void consider_contact(detail::Event& best, std::uint32_t other, double t) const;
  [[nodiscard]] std::uint32_t meeting(std::uint32_t ball, const std::uint32_t* others,
                                      std::uint32_t lanes) const;
  // Brings one ball, or every ball, to time t (its position advanced along its velocity).
  void advance(std::uint32_t ball, double t);
  // advance's part for a world with gravity (world_gravity.cpp): the velocity is re-based too.
  void advance_under_gravity(std::uint32_t ball, double t);
  void synchronize(double t);

  // ---- the event loop (world_run.cpp) ----
  // What a run was asked for: to reach a time (step, run_until), or a count of contacts
  // (run_collisions, whose end time is a limit).
  enum class RunGoal : std::uint8_t { time, contacts };
  // Processes events in order until time `end` or `max_contacts` contacts; returns the contacts
  // and leaves why it returned in stop_reason. Throws InvalidArgument (naming `function`) when
  // contacts at one instant do not end.
  std::uint64_t run(const char* function, RunGoal goal, double end, std::uint64_t max_contacts);
  // The run's watch over runs that would never end (world_run.cpp).
  struct RunGuard;
  // Whether a stop was asked for (request_stop, or the progress callback); clears the request.
  [[nodiscard]] bool stop_asked(const RunStatus& status);
  // True only when no contact can ever happen again, by the rules in world_no_contact.cpp;
  // false means "not proven", not "a contact will happen".
  [[nodiscard]] bool no_contact_ever() const;
  // ---- response (world_response.cpp) and cell crossing (world_cell_crossing.cpp) ----
  bool process(const detail::Event& event);  // true when a contact was resolved
  // Whether a contact's balls have moved measurably in `elapsed` (run's jam detection).
  [[nodiscard]] bool moved_measurably(const detail::Event& contact, double elapsed) const;
  // Large worlds: asks the cache, stage by stage, for the data of the events in the buckets
  // ahead of the queue's current one (world_lookahead.cpp); called when that bucket changes.
  // Only prefetches: changes no result.
  void look_ahead();
  void lookahead_noted();
  void lookahead_walk(std::int64_t current);
  void lookahead_enter(std::int64_t bucket);
  void lookahead_stage_0(std::uint32_t ball) const;
  void lookahead_stage_1(std::uint32_t ball);
  void lookahead_block(std::int32_t cx, std::int32_t cy);
  // Whether the rounding of the world's time moves one of an event's balls measurably.
  [[nodiscard]] bool time_too_coarse(const detail::Event& event) const;
  // Refuses a run whose time is too large for its balls' motion ("has stalled").
  [[noreturn]] void refuse_stalled(const char* function, const detail::Event& last) const;
  // Refuses a run that would never end after `count` events at one instant or contacts without
  // motion, the last of them `last`: a jam, or a stall of time.
  [[noreturn]] void refuse_endless(const char* function, std::uint64_t count,
                                   const detail::Event& last) const;
  bool resolve_ball_ball(std::uint32_t i, std::uint32_t j, double t);
  // Refuses a run whose contacts pile up towards one instant (contact_pace.hpp), `last` the
  // latest.
  [[noreturn]] void refuse_piling_up(const char* function, const detail::Event& last) const;
  // Refuses a run that would never end (`where` and `how` say what was seen), naming its likely
  // cause: balls crushed by a moving immovable ball, else an inelastic collapse where `last`'s
  // balls bounce inelastically without collapse_time, else `otherwise`.
  [[noreturn]] void refuse_never_ending(const char* function, const std::string& where,
                                        const std::string& how, const detail::Event& last,
                                        const std::string& otherwise) const;
  // (share: where the contact point divides `between`, from i; negative: by the radii.)
  void record_ball_ball(std::uint32_t i, std::uint32_t j, double t, Vec2 between, Vec2 normal,
                        double approach, double impulse, double share = -1.0);
  bool resolve_ball_wall(std::uint32_t i, std::uint32_t wall, double t);
  // Records a ball's contact with a wall (and its time, for collapse_time); the impulse is the
  // speed change times the mass (0 for an immovable ball).
  void record_ball_wall(std::uint32_t i, std::uint32_t wall, double t, Vec2 point, Vec2 normal,
                        double approach, double speed_change);
  // A ball leaving its cell through `side` at t: moved to the next cell and predicted, looking only
  // at the cells the crossing brings into reach where its last prediction found no contact
  // around it (clear_behind; docs/engine.md, "Crossing a cell").
  void cross_cell(std::uint32_t ball, std::uint32_t side, double t, bool clear_behind);
  // The restitution a pair bounces with at t: the smaller of theirs, or 1 for a ball that
  // collided recently (below).
  [[nodiscard]] double pair_restitution(std::uint32_t i, std::uint32_t j, double t) const {
    if (collided_recently(i, t) || collided_recently(j, t)) return 1.0;
    if (!mixed_restitution) return def.restitution;
    return std::min(species_of(i).restitution, species_of(j).restitution);
  }
  // Whether a ball collided less than def.collapse_time before t (always false when it is 0):
  // inelastic collapse prevention (the TC model; docs/engine.md, "Response"), under which such
  // a ball bounces elastically.
  [[nodiscard]] bool collided_recently(std::uint32_t ball, double t) const {
    return def.collapse_time > 0.0 && last_contact_times[ball] > t - def.collapse_time;
  }
};

}  // namespace carom
