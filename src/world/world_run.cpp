// The event loop: events processed in time order until a run's end, and the refusals of runs
// that would never end (docs/engine.md, "The event loop", "Runs that would never end").
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "carom/error.hpp"
#include "cell_exit.hpp"
#include "contact_pace.hpp"
#include "core/bowl_bounce.hpp"
#include "core/circle_crossing.hpp"
#include "core/impulse.hpp"
#include "core/validate.hpp"
#include "engine_tuning.hpp"
#include "pair_batch.hpp"
#include "permute.hpp"
#include "prediction_steps.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Event;
using detail::EventKind;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

// ---- the event loop -----------------------------------------------------------------------

bool World::Impl::stop_asked(const RunStatus& status) {
  // exchange only when set: the common case stays a plain load.
  if (stop_requested.load(std::memory_order_relaxed) &&
      stop_requested.exchange(false, std::memory_order_relaxed)) {
    return true;
  }
  return progress_callback && progress_callback(status);
}

// What a run watches besides its events: the runs that would never end (docs/world.md, "Known
// limits"), each refused with a message naming its likely cause, and, for a run with no end time,
// when to try proving that no contact will ever happen. The loop tells it of each event; it keeps
// the counts, so that the loop reads as a loop.
struct World::Impl::RunGuard {
  RunGuard(const Impl& of, const char* calling, bool without_end)
      : world(of),
        function(calling),
        unbounded(without_end),
        endless(kInstantEventsPerBall * of.live_count + kInstantEventsFloor),
        next_proof(std::max<std::uint64_t>(kEventsBeforeProof, 2 * of.live_count)) {}

  // Any event: events at one instant (or a rounding apart) without end are a jam, or a time
  // too large to advance.
  CAROM_ALWAYS_INLINE void after_event(const Event& event) {
    if (world.time != instant) {
      instant = world.time;
      at_instant = 0;
    } else if (++at_instant > endless) {
      world.refuse_endless(function, at_instant, event);
    }
  }

  // An event that was no contact (a cell crossing, a contact that did not happen): any event at
  // a time too coarse for its balls is refused as a contact would be. A predicted contact whose
  // balls were then found not to meet (a rounding short of it or past it) was lost to rounding,
  // not missed by a hair (a ball of radius 10⁻⁶ at t = 2.7·10¹¹ went through a wall so), and a
  // cell crossing taken a rounding late puts its ball past the next cell, past the box's wall
  // (one at t = 4.4·10¹⁷ left the box so). Returns whether to try the proof that no contact
  // will come: after a stretch of events without one (a run with no end time only), each failed
  // proof doubling the stretch, so that proofs (O(N²)) stay rare.
  CAROM_ALWAYS_INLINE bool after_no_contact(const Event& event) {
    // (A ball a sensor removed is gone too: nothing of it to measure.)
    const bool gone = (event.kind == EventKind::ball_ball && !world.balls[event.partner].alive()) ||
                      (event.kind == EventKind::ball_wall && !world.balls[event.owner].alive());
    if (!gone && world.time_too_coarse(event)) world.refuse_stalled(function, event);
    return unbounded && ++without_contact >= next_proof;
  }
  void proof_failed() {
    next_proof *= 2;
    without_contact = 0;
  }

  // A contact: refused where time is too coarse for it, where contacts pile up towards an
  // instant (each with motion: a crush), and where contacts go on without measurable motion
  // (a jam).
  CAROM_ALWAYS_INLINE void after_contact(const Event& event) {
    without_contact = 0;
    const double now = world.time;
    if (world.time_too_coarse(event)) world.refuse_stalled(function, event);
    if (pace.piling_up(now)) world.refuse_piling_up(function, event);
    if (world.moved_measurably(event, now - motion_time)) {
      motion_time = now;
      contacts_without_motion = 0;
    } else if (++contacts_without_motion > endless) {
      world.refuse_endless(function, contacts_without_motion, event);
    }
  }

  const Impl& world;
  const char* function;
  const bool unbounded;  // no end time: contacts may end for good
  const std::uint64_t endless;
  std::uint64_t without_contact = 0;
  std::uint64_t next_proof;
  double instant = -kInfinity;
  std::uint64_t at_instant = 0;
  double motion_time = -kInfinity;
  std::uint64_t contacts_without_motion = 0;
  detail::ContactPace pace;
};

std::uint64_t World::Impl::run(const char* function, RunGoal goal, double end,
                               std::uint64_t max_contacts) {
  // However the run ends, the moving walls' shapes are brought to its end (queries, the audit
  // and wall() read them).
  struct PlaceWallsAtEnd {
    Impl& world;
    explicit PlaceWallsAtEnd(Impl& w) : world(w) {}
    PlaceWallsAtEnd(const PlaceWallsAtEnd&) = delete;
    PlaceWallsAtEnd& operator=(const PlaceWallsAtEnd&) = delete;
    ~PlaceWallsAtEnd() {
      if (!world.moving_walls.empty()) world.place_moving_walls();
    }
  } place_walls_at_end{*this};
  contacts.clear();
  sensor_events.clear();
  motion_events.clear();
  stop_reason = StopReason::none;
  mover_met = false;
  if (!grid_valid || grid_too_coarse(live_count, kRunCoarseness)) rebuild_grid(Vec2{}, 0.0);
  if (!events_valid) predict_all();
  queue.use_handles(handle_of.data());  // add_ball may have moved the array
  RunGuard guard(*this, function, end == kInfinity);
  const bool prefetching = live_count >= kPrefetchMinBalls;
  lookahead.deep = live_count >= kDeepLookaheadMinBalls;
  // Filing is deferred during the run only, however it ends (a refusal throws).
  struct DeferredFiling {
    detail::EventQueue& queue;
    DeferredFiling(detail::EventQueue& q, bool on) : queue(q) { queue.defer_filing(on); }
    DeferredFiling(const DeferredFiling&) = delete;
    DeferredFiling& operator=(const DeferredFiling&) = delete;
    ~DeferredFiling() { queue.defer_filing(false); }
  } deferred_filing(queue, prefetching);
  const std::uint64_t sort_after = kSortEvents * live_count + kSortMinEvents;
  // Stop requests are looked at before the first event and then every kStopCheckEvents events.
  static_assert(std::has_single_bit(kStopCheckEvents));
  std::uint64_t events = 0;
  std::uint64_t resolved = 0;
  for (;;) {
    if ((events & (kStopCheckEvents - 1)) == 0 && stop_asked({time, events, resolved})) {
      stop_reason = StopReason::interrupted;
      return resolved;
    }
    ++events;
    if (++events_since_sort > sort_after) sort_by_cell();
    const Event event = queue.top();
    if (growth_on && event.time > growth_regrid_time && growth_regrid_time <= end) [[unlikely]] {
      // The largest ball outgrows the cells before this event: the grid is re-planned then, and
      // every prediction renewed.
      regrid_for_growth(std::max(growth_regrid_time, time));  // (never back in time)
      continue;
    }
    if (!(event.time <= end) || event.time == kInfinity) {
      // Reaching the time asked for is what a timed run is for; for a count of contacts, an end
      // of the queue means none will ever come, and a finite end is the caller's limit.
      if (goal == RunGoal::contacts) {
        stop_reason =
            event.time == kInfinity ? StopReason::no_more_contacts : StopReason::time_limit;
      }
      break;
    }
    if (prefetching && queue.current_bucket() != lookahead.passed_bucket) look_ahead();
    time = event.time;
    const bool contact = process(event);
    guard.after_event(event);
    if (!contact) {
      if (guard.after_no_contact(event)) {
        if (no_contact_ever()) {
          stop_reason = StopReason::no_more_contacts;
          break;
        }
        guard.proof_failed();
      }
      continue;
    }
    ++resolved;
    ++collisions;
    guard.after_contact(event);
    const bool stop = stop_condition && stop_condition(last_contact);
    if (stop || resolved == max_contacts) {
      if (stop) stop_reason = StopReason::stop_condition;
      return resolved;
    }
  }
  // Balls stay at their own local times: queries compute positions at the world's time, so
  // splitting a run into steps changes nothing (no re-rounding of positions at step ends).
  if (end < kInfinity) time = end;
  return resolved;
}

CAROM_ALWAYS_INLINE inline bool World::Impl::moved_measurably(const Event& contact,
                                                              double elapsed) const {
  if (elapsed == kInfinity) return true;  // the run's first contact
  const auto moved = [&](std::uint32_t ball) {
    const BallSlot& b = balls[ball];
    // |x| + |y| bounds the length within a factor √2, which is all a threshold needs.
    const double travel = elapsed * (std::abs(b.velocity.x) + std::abs(b.velocity.y));
    const double size = std::abs(b.position.x) + std::abs(b.position.y) + radius_of(ball);
    return travel > kMeasurableMotion * size;
  };
  return moved(contact.owner) || (contact.kind == EventKind::ball_ball && moved(contact.partner));
}

CAROM_ALWAYS_INLINE inline bool World::Impl::time_too_coarse(const Event& event) const {
  // Neighbouring doubles near t are at most t·2⁻⁵² apart.
  const double time_step = std::abs(time) * 0x1p-52;
  const auto coarse = [&](std::uint32_t ball) {
    const BallSlot& b = balls[ball];
    const double motion = time_step * (std::abs(b.velocity.x) + std::abs(b.velocity.y));
    return motion > kResolvableMotion * radius_of(ball);
  };
  return coarse(event.owner) || (event.kind == EventKind::ball_ball && coarse(event.partner));
}

void World::Impl::refuse_endless(const char* function, std::uint64_t count,
                                 const Event& last) const {
  // Time stalls where its step to the next double would move the event's ball measurably: the
  // motion between events is then lost to rounding. Otherwise the balls are jammed.
  const double time_step = std::nextafter(time, kInfinity) - time;
  // (A ball a sensor removed has nothing left to measure.)
  const bool gone = !balls[last.owner].alive() ||
                    (last.kind == EventKind::ball_ball && !balls[last.partner].alive());
  if (!gone && moved_measurably(last, time_step)) refuse_stalled(function, last);
  refuse_never_ending(
      function, std::to_string(count) + " events at t = " + carom::number_text(time),
      "their contacts come at one instant (or a rounding apart) without end", last,
      "has balls jammed: balls held by touching balls and walls on every side (a closed row of "
      "exactly touching balls around the periodic cell or from wall to wall, a ball wedged in a "
      "corner) pass their contacts on without moving, for ever; leave a gap (docs/world.md, "
      "\"Known limits\")");
}

void World::Impl::refuse_piling_up(const char* function, const Event& last) const {
  const std::string how =
      "contacts come ever faster, infinitely often before one instant (each doubling of the "
      "run's contact count took under 3/4 of the time of the one before, 8 times in a row)";
  refuse_never_ending(
      function,
      "t = " + carom::number_text(time) + " (ball " + std::to_string(handle_of[last.owner]) + ")",
      how, last, "has contacts piling up: " + how + " (docs/world.md, \"Known limits\")");
}

void World::Impl::refuse_never_ending(const char* function, const std::string& where,
                                      const std::string& how, const Event& last,
                                      const std::string& otherwise) const {
  if (mover_met) {
    throw InvalidArgument(function, "world", where,
                          "has balls crushed: a moving immovable ball or a moving wall closes on "
                          "balls against a wall or an immovable ball, and " +
                              how + "; stop it first (docs/world.md, \"Known limits\")");
  }
  const bool inelastic = def.collapse_time == 0.0 &&
                         (restitution_of(last.owner) < 1.0 || (last.kind == EventKind::ball_ball &&
                                                               restitution_of(last.partner) < 1.0));
  if (inelastic) {
    throw InvalidArgument(function, "world", where,
                          "has an inelastic collapse: balls with restitution below 1 pressed "
                          "together (against a wall, or in a cluster) meet again and again, and " +
                              how +
                              "; set WorldDef::collapse_time (a ball that met something less "
                              "than that long ago then bounces elastically; docs/world.md, "
                              "\"Known limits\")");
  }
  throw InvalidArgument(function, "world", where, otherwise);
}

void World::Impl::refuse_stalled(const char* function, const Event& last) const {
  throw InvalidArgument(
      function, "world",
      "t = " + carom::number_text(time) + " (ball " + std::to_string(handle_of[last.owner]) + ")",
      "has stalled: at this time the step between neighbouring doubles moves a ball measurably "
      "(more than 2^-10 of its radius), so contacts would be resolved off their places, and "
      "events may no longer advance time at all; continue the motion in a new world, from time "
      "0 (docs/world.md, \"Known limits\")");
}

}  // namespace carom
