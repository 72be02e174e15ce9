// carom internal: the engine's tuning, in one place: each constant with why it has its value.
// Read by the parts of world_*.cpp; docs/engine.md explains the mechanisms they tune.
#pragma once

#include <cstdint>
#include <limits>

namespace carom::detail::tuning {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The horizon handed to a time-of-impact query when nothing earlier bounds it.
inline constexpr double kFarFuture = std::numeric_limits<double>::max();
// An open world's grid covers the balls and walls with this much room on each side (as a
// fraction of their extent), so that it is rebuilt only every so often as balls spread out.
inline constexpr double kOpenGrowth = 0.5;
// ... and at least this fraction of the coordinates' size (far above their rounding, 2⁻⁵²).
inline constexpr double kRoomOfScale = 0x1p-40;
// At most this many cells per ball (plus a floor), so that a ball far away makes cells larger
// rather than the grid huge.
inline constexpr double kCellsPerBall = 4.0;
inline constexpr double kMinCells = 1024.0;
// A dilute world (fewer balls than this per cell of the smallest size) gets cells kDiluteCells
// times that size, and the room beyond the diameter becomes the cells' hysteresis: a ball then
// leaves its cell only this far past its side, so that one turning back near a side does not
// cross twice (docs/engine.md, "The broad phase"). In a dilute gas it cuts the crossings a
// collision by a third; in denser gases crossings are few and the larger blocks cost more than
// they save (docs/decisions/0006-grid-cells-and-hysteresis.md).
inline constexpr double kDiluteBallsPerCell = 0.55;
inline constexpr double kDiluteCells = 1.25;
// The share of that room given to the hysteresis: all but a sliver, so that the cell less twice
// the hysteresis stays above the diameter after rounding (and at most detail::kMostHysteresis
// of the cell).
inline constexpr double kHysteresisShare = 0.999;
// A grid is re-planned while balls are added once a re-plan would make its cells this much
// smaller per side (the ball count has grown about 4 times: O(1) amortised per add_ball) ...
inline constexpr double kAddCoarseness = 2.0;
// ... and before a run once it would make them any smaller beyond the floor-rounding of the cell
// count, so that a run never keeps cells coarser than it needs (a run's re-plan is paid once).
inline constexpr double kRunCoarseness = 1.01;
// The slots are re-ordered by cell (sort_by_cell) once the events since the last time exceed
// this many per ball (plus a floor, so that small worlds, which fit in cache anyway, are rarely
// re-ordered). A re-order costs about as much as a few events per ball; in between, balls
// drift only a few cells from their neighbours in memory.
inline constexpr std::uint64_t kSortEvents = 8;
inline constexpr std::uint64_t kSortMinEvents = 1 << 16;
// A grid with at least this many cells per axis has interior cells whose 3×3 block needs no
// minimum image (predict).
inline constexpr std::int32_t kInteriorMinCells = 5;
// A periodic grid with at least this many cells per axis needs only the nearest image of each
// pair: between two predictions of a pair neither ball leaves its cell, so their offset moves
// by under two cells per axis, and a pair that touches (within one cell) was within three cells
// when predicted, under half a period from 7 cells on (6 leaves no room for the cell margin).
inline constexpr std::int32_t kSingleImageMinCells = 7;
// Contacts without measurable motion (a jammed chain of touching balls), or events at one
// instant (a jam, or time too large to advance), beyond this many per ball plus a floor mean a
// run that would never end (docs/world.md, "Known limits"). A Newton's cradle has one contact a
// ball at one instant, a break from rest a few.
inline constexpr std::uint64_t kInstantEventsPerBall = 100;
inline constexpr std::uint64_t kInstantEventsFloor = 1 << 16;
// A contact counts as motion when one of its balls has travelled more than this fraction of its
// coordinates' size (|x| + |y| + radius) since the last one that did: a jammed ball creeps a
// rounding at a time, so its contacts advance time by ulps rather than not at all.
inline constexpr double kMeasurableMotion = 0x1p-30;
// A contact is refused (time "has stalled") where one step of the double grid of time moves one
// of its balls by more than this fraction of its radius: contacts are resolved at event times
// rounded to that grid, so they would land that far off their places (and overlaps of that
// size are beyond what World::audit allows for the rounding of positions). Speed 1 and radius 1
// reach it at t ≈ 4·10¹²; a ball of radius 10⁻⁶ at speed 100 at t ≈ 3·10⁴.
inline constexpr double kResolvableMotion = 0x1p-10;
// Events without a contact before run_collisions first tries to prove that none will come
// (at least; 2 per ball in larger worlds, where one crossing per ball is ordinary).
inline constexpr std::uint64_t kEventsBeforeProof = 64;
// Worlds with at least this many balls look ahead (world_lookahead.cpp: the data of the events
// in the queue's next buckets asked for, stage by stage) and defer filing events (event_queue.hpp).
// Where everything is in cache both only cost their instructions, so they start where the world
// outgrows the caches (docs/decisions/0013-lookahead-in-large-worlds.md).
inline constexpr std::uint32_t kPrefetchMinBalls = 1u << 16;
// ... and from this many on, their lookahead goes a stage deeper (world_lookahead.cpp), which
// pays once the arrays are several times the last-level cache (the same record).
inline constexpr std::uint32_t kDeepLookaheadMinBalls = 90'000;

}  // namespace carom::detail::tuning
