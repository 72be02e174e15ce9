// World::save and World::load: everything that decides a world's future, so that a resumed run
// is bit-identical to an uninterrupted one. Format and the reasoning behind what is saved:
// docs/world.md, "Saving and resuming".
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "carom/atomic_file.hpp"
#include "carom/error.hpp"
#include "core/validate.hpp"
#include "save_format.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::ByteReader;
using detail::ByteWriter;

namespace {

constexpr char kMagic[8] = {'C', 'A', 'R', 'O', 'M', 'W', 'L', 'D'};
// 2: the grid's hysteresis (docs/world.md, "Saving and resuming"). A version-1 save is refused:
// it was written by an engine whose run this build would not continue bit for bit anyway.
// 3: version 2 with gravity and the rest height after the cell size, and each slot's carriage
// (resting and sliding); written only for a world with gravity, so that a world without it saves
// exactly the bytes it always did.
// 4: version 2 with the growth rate, the rate relative to the radii saved, its start and the
// grid's re-planning time after the cell size; written only for a world whose balls grow.
constexpr std::uint32_t kVersion = 2;
constexpr std::uint32_t kGravityVersion = 3;
constexpr std::uint32_t kGrowthVersion = 4;
// Added to any of them: the world has collision filters, saved after everything else (the
// filter table, then each ball's filter number in handle order, then each wall's), so that a
// world without filters saves exactly the bytes it always did.
constexpr std::uint32_t kFiltersFlag = 0x100;
// Added likewise: the world has sensors (a sensor's disc is wall kind 2), saved after the filters:
// each wall's sensor role, then the (ball, sensor) pairs recorded inside.
constexpr std::uint32_t kSensorsFlag = 0x200;
// Added likewise: some wall moves or was removed, saved last: each such wall's id, whether it was
// removed, and a moving wall's path (its rigid motion, start and end, and its shape at the start,
// the arc's prepared frame included).
constexpr std::uint32_t kWallChangesFlag = 0x400;
// Added likewise: the world has a table, saved last: its definition, then each slot's spin,
// twist and motion state (the state's acceleration and end as they were set when it began).
constexpr std::uint32_t kTableFlag = 0x800;
constexpr std::uint32_t kFlags = kFiltersFlag | kSensorsFlag | kWallChangesFlag | kTableFlag;
constexpr std::size_t kHeaderSize = sizeof kMagic + 4 + 8 + 8;  // magic, version, size, checksum
// Payloads are read in pieces of this size, so that a damaged size field cannot make load
// allocate more than the stream really holds.
constexpr std::size_t kReadChunk = std::size_t{1} << 20;

void put_u32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
}
void put_u64(std::string& out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
}
std::uint64_t get_unsigned(const char* bytes, int count) {
  std::uint64_t value = 0;
  for (int i = 0; i < count; ++i) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i])) << (8 * i);
  }
  return value;
}

std::string framed(const std::string& payload, std::uint32_t version) {
  std::string out(kMagic, sizeof kMagic);
  put_u32(out, version);
  put_u64(out, payload.size());
  put_u64(out, detail::fnv1a64(payload));
  return out + payload;
}

[[noreturn]] void damaged(const char* function, const std::string& source, const std::string& value,
                          const std::string& why) {
  throw InvalidArgument(function, source, value, why);
}

// Reads the header and the payload it announces, checking magic, version, length and checksum.
std::string read_payload(const char* function, const std::string& source, std::istream& in,
                         std::uint32_t& version) {
  char header[kHeaderSize];
  in.read(header, kHeaderSize);
  const auto header_read = static_cast<std::size_t>(in.gcount());
  if (header_read < sizeof kMagic || std::memcmp(header, kMagic, sizeof kMagic) != 0) {
    damaged(function, source, std::to_string(header_read) + " bytes",
            "bad magic: not a carom world save (it starts with \"CAROMWLD\")");
  }
  if (header_read < kHeaderSize) {
    damaged(function, source, std::to_string(header_read) + " bytes",
            "truncated: the header needs " + std::to_string(kHeaderSize) + " bytes");
  }
  version = static_cast<std::uint32_t>(get_unsigned(header + 8, 4));
  const std::uint32_t base = version & ~kFlags;
  if (base != kVersion && base != kGravityVersion && base != kGrowthVersion) {
    damaged(function, source, "version " + std::to_string(version),
            "unsupported version (this build reads versions " + std::to_string(kVersion) + ", " +
                std::to_string(kGravityVersion) + " and " + std::to_string(kGrowthVersion) + ")");
  }
  const std::uint64_t size = get_unsigned(header + 12, 8);
  const std::uint64_t checksum = get_unsigned(header + 20, 8);
  std::string payload;
  while (payload.size() < size) {
    const std::size_t want =
        static_cast<std::size_t>(std::min<std::uint64_t>(kReadChunk, size - payload.size()));
    const std::size_t old_size = payload.size();
    payload.resize(old_size + want);
    in.read(payload.data() + old_size, static_cast<std::streamsize>(want));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got < want) {
      damaged(function, source, std::to_string(old_size + got) + " payload bytes",
              "truncated: the header announces " + std::to_string(size) + " payload bytes");
    }
  }
  const std::uint64_t actual = detail::fnv1a64(payload);
  if (actual != checksum) {
    damaged(function, source, "FNV-1a " + std::to_string(actual),
            "checksum mismatch: the header says " + std::to_string(checksum) +
                " (the file is damaged)");
  }
  return payload;
}

bool finite(Vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

}  // namespace

// ---- writing ---------------------------------------------------------------------------------

std::string World::Impl::save_payload() const {
  ByteWriter out;
  out.u8(static_cast<std::uint8_t>(def.boundary));
  out.vec2(def.lower);
  out.vec2(def.upper);
  out.f64(def.restitution);
  out.f64(def.collapse_time);
  out.f64(def.cell_size);
  if (gravity_on) {
    out.vec2(def.gravity);
    out.f64(def.rest_height);
  }
  if (growth_on) {
    out.f64(def.growth_rate);
    out.f64(growth_relative);
    out.f64(growth_start);
    out.f64(growth_regrid_time);
  }

  out.f64(time);
  out.u64(collisions);
  out.f64(largest_radius);
  out.u8(record_contacts ? 1 : 0);
  out.u8(grid_valid ? 1 : 0);
  out.u8(events_valid ? 1 : 0);

  out.u32(static_cast<std::uint32_t>(walls.size()));
  for (const detail::Wall& wall : walls) {
    out.u8(wall.is_disc ? 2 : wall.is_arc ? 1 : 0);
    if (wall.is_disc) {
      out.vec2(wall.disc.center);
      out.f64(wall.disc.radius);
    } else if (wall.is_arc) {
      out.vec2(wall.arc.center);
      out.f64(wall.arc.radius);
      out.f64(wall.arc.start_angle);
      out.f64(wall.arc.end_angle);
    } else {
      out.vec2(wall.segment.a);
      out.vec2(wall.segment.b);
    }
  }

  // Balls in handle order, every ball named by its handle index: the file does not depend on
  // where the engine stores balls (sort_by_cell), and a loaded world stores them in this order.
  const auto slots = static_cast<std::uint32_t>(balls.size());
  out.u32(slots);
  for (const std::uint32_t i : slot_of_handle) {
    const detail::BallSlot& b = balls[i];
    const detail::BallInfo& info = infos[i];
    // A free slot keeps no species: its kind is written as zeros (load ignores it).
    const detail::Species kind = b.alive() ? species_of(i) : detail::Species{0.0, 0.0, 0.0, 0, 0.0};
    out.u8(b.alive() ? 1 : 0);
    out.vec2(b.position);
    out.vec2(b.velocity);
    out.f64(b.local_time);
    out.f64(kind.radius);
    out.f64(kind.inverse_mass);
    out.u32(b.version);
    out.f64(kind.mass);
    out.f64(kind.restitution);
    out.u64(info.user_data);
    out.u32(info.generation);
    if (def.collapse_time > 0.0) out.f64(last_contact_times[i]);
    if (gravity_on) {
      const detail::Carriage& c = carriages[i];
      out.u8(static_cast<std::uint8_t>(c.state));
      out.u8(c.supports);
      out.u32(c.support[0]);
      out.u32(c.support[1]);
      out.vec2(c.acceleration);
      out.vec2(c.normal);
      out.vec2(c.origin);
      out.f64(c.lower);
      out.f64(c.upper);
    }
  }
  out.u32(static_cast<std::uint32_t>(free_handles.size()));
  for (const std::uint32_t slot : free_handles) out.u32(slot);

  if (grid_valid) {
    out.vec2(grid.lower());
    out.vec2(grid.cell_size());
    out.vec2(grid.hysteresis());
    out.i32(grid.nx());
    out.i32(grid.ny());
    for (const std::uint32_t i : slot_of_handle) {
      out.i32(balls[i].alive() ? grid.cell_of_ball(i) : -1);
    }
    // The balls in the order of the cells' lists, so that load rebuilds every list in the same
    // order (prediction's result does not depend on it, but the engine's path then is the same).
    const std::int32_t cells = grid.nx() * grid.ny();
    for (std::int32_t c = 0; c < cells; ++c) {
      for (std::int32_t j = grid.first_ball(c); j != detail::kNoBall;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        out.u32(handle_of[static_cast<std::uint32_t>(j)]);
      }
    }
  }
  if (events_valid) {
    // Every ball's pending event as predicted, stale ones included: they were computed from
    // earlier positions and cannot be re-derived from the state above.
    for (const std::uint32_t i : slot_of_handle) {
      const detail::Event event = queue.slot(i);
      out.f64(event.time);
      out.u8(static_cast<std::uint8_t>(event.kind));
      out.u32(event.kind == detail::EventKind::ball_ball ? handle_of[event.partner]
                                                         : event.partner);
      out.u32(event.partner_version);
    }
  }
  if (filters.active()) {
    out.u32(static_cast<std::uint32_t>(filters.size()));
    for (const CollisionFilter& f : filters.all()) {
      out.u64(f.category);
      out.u64(f.mask);
      out.i32(f.group);
    }
    for (const std::uint32_t i : slot_of_handle) out.u32(infos[i].filter);
    for (const detail::Wall& wall : walls) out.u32(wall.filter);
  }
  if (has_sensors()) {
    for (const detail::Wall& wall : walls) out.u8(static_cast<std::uint8_t>(wall.sensor));
    out.u64(sensor_inside.size());
    for (const std::uint64_t key : sensor_inside) out.u64(key);
  }
  if (has_wall_changes()) {
    std::uint32_t changed = 0;
    for (const detail::Wall& wall : walls) changed += wall.moving || wall.removed ? 1U : 0U;
    out.u32(changed);
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
      const detail::Wall& wall = walls[w];
      if (!wall.moving && !wall.removed) continue;
      out.u32(w);
      out.u8(wall.removed ? 1 : 0);
      out.u8(wall.moving ? 1 : 0);
      if (!wall.moving) continue;
      const detail::WallPath& path = wall.path;
      out.vec2(path.rigid.velocity);
      out.f64(path.rigid.angular_velocity);
      out.vec2(path.rigid.pivot);
      out.f64(path.start);
      out.f64(path.until);
      if (wall.is_arc) {
        out.vec2(path.arc.center);
        out.f64(path.arc.radius);
        out.f64(path.arc.start_angle);
        out.f64(path.arc.end_angle);
        out.vec2(path.frame.center);
        out.f64(path.frame.radius);
        out.f64(path.frame.span);
        out.vec2(path.frame.start_direction);
        out.vec2(path.frame.end_direction);
        out.vec2(path.frame.start_point);
        out.vec2(path.frame.end_point);
      } else {
        out.vec2(path.segment.a);
        out.vec2(path.segment.b);
      }
    }
  }
  if (table_on) save_table(out);
  return out.bytes();
}

void World::Impl::save_table(detail::ByteWriter& out) const {
  const Table& table = *def.table;
  for (const double value :
       {table.g, table.sliding_friction, table.rolling_friction, table.spinning_friction,
        table.ball_friction, table.cushion_height, table.cushion_restitution,
        table.cushion_friction, table.contact_time}) {
    out.f64(value);
  }
  for (const std::uint32_t i : slot_of_handle) {
    const detail::TableSlot& slot = table_slots[i];
    out.vec2(slot.spin);
    out.f64(slot.twist);
    out.vec2(slot.acceleration);
    out.f64(slot.ends);
    out.u8(static_cast<std::uint8_t>(slot.state));
  }
}

std::uint32_t World::Impl::save_version() const {
  const std::uint32_t flags =
      (filters.active() ? kFiltersFlag : 0U) | (has_sensors() ? kSensorsFlag : 0U) |
      (has_wall_changes() ? kWallChangesFlag : 0U) | (table_on ? kTableFlag : 0U);
  if (gravity_on) return kGravityVersion | flags;
  return (growth_on ? kGrowthVersion : kVersion) | flags;
}

void World::save(std::ostream& out) const {
  const std::string bytes = framed(impl_->save_payload(), impl_->save_version());
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.flush();
  if (!out) {
    throw InvalidArgument("World::save", "out", "-", "the stream failed while writing");
  }
}

void World::save(const std::filesystem::path& path) const {
  try {
    write_file_atomically(path, framed(impl_->save_payload(), impl_->save_version()));
  } catch (const FileError& error) {
    throw InvalidArgument("World::save", "path", path.string(), error.reason());
  }
}

// ---- reading ---------------------------------------------------------------------------------

void World::Impl::load_payload(ByteReader& in, std::uint32_t flagged_version) {
  const std::uint32_t version = flagged_version & ~kFlags;
  using carom::number_text;
  using detail::vector_text;
  const std::uint8_t boundary = in.u8("def.boundary");
  if (boundary > static_cast<std::uint8_t>(Boundary::periodic)) {
    in.inconsistent("def.boundary", std::to_string(boundary), "not a Boundary (0, 1 or 2)");
  }
  def.boundary = static_cast<Boundary>(boundary);
  def.lower = in.vec2("def.lower");
  def.upper = in.vec2("def.upper");
  def.restitution = in.f64("def.restitution");
  def.collapse_time = in.f64("def.collapse_time");
  def.cell_size = in.f64("def.cell_size");
  if (version == kGravityVersion) {
    def.gravity = in.vec2("def.gravity");
    if (!finite(def.gravity) || def.gravity == Vec2{}) {
      in.inconsistent("def.gravity", vector_text(def.gravity), "must be finite and not zero");
    }
    def.rest_height = in.f64("def.rest_height");
    if (!(def.rest_height > 0.0 && std::isfinite(def.rest_height))) {
      in.inconsistent("def.rest_height", number_text(def.rest_height), "must be finite, > 0");
    }
    gravity_on = true;
  }
  if (version == kGrowthVersion) {
    def.growth_rate = in.f64("def.growth_rate");
    if (!(def.growth_rate > 0.0 && std::isfinite(def.growth_rate))) {
      in.inconsistent("def.growth_rate", number_text(def.growth_rate), "must be finite, > 0");
    }
    growth_relative = in.f64("growth relative rate");
    if (!(growth_relative > 0.0 && std::isfinite(growth_relative))) {
      in.inconsistent("growth relative rate", number_text(growth_relative), "must be finite, > 0");
    }
    growth_start = in.f64("growth start");
    if (!std::isfinite(growth_start)) {
      in.inconsistent("growth start", number_text(growth_start), "must be finite");
    }
    growth_regrid_time = in.f64("growth re-planning time");
    if (std::isnan(growth_regrid_time)) {
      in.inconsistent("growth re-planning time", "NaN", "must be a time");
    }
    growth_on = true;
  }
  table_on = (flagged_version & kTableFlag) != 0;
  if (table_on && (gravity_on || growth_on)) {
    in.inconsistent("version", std::to_string(flagged_version),
                    "a table goes with neither gravity nor growth");
  }
  accelerated = gravity_on || table_on;
  general_motion = gravity_on || growth_on || table_on;
  if (def.boundary != Boundary::open && !(finite(def.lower) && finite(def.upper) &&
                                          def.upper.x > def.lower.x && def.upper.y > def.lower.y)) {
    in.inconsistent("def.upper", vector_text(def.upper),
                    "must be finite and lie above and to the right of def.lower");
  }
  if (!(def.restitution >= 0.0 && def.restitution <= 1.0)) {
    in.inconsistent("def.restitution", number_text(def.restitution), "must lie in [0, 1]");
  }
  if (!(def.collapse_time >= 0.0 && std::isfinite(def.collapse_time))) {
    in.inconsistent("def.collapse_time", number_text(def.collapse_time), "must be finite, >= 0");
  }
  if (!(def.cell_size >= 0.0 && std::isfinite(def.cell_size))) {
    in.inconsistent("def.cell_size", number_text(def.cell_size), "must be finite, >= 0");
  }
  periodic_cell = PeriodicCell(def.lower, def.upper);

  time = in.f64("time");
  if (!std::isfinite(time)) in.inconsistent("time", number_text(time), "must be finite");
  collisions = in.u64("collision count");
  largest_radius = in.f64("largest radius");
  record_contacts = in.u8("contact recording") != 0;
  grid_valid = in.u8("grid valid") != 0;
  events_valid = in.u8("events valid") != 0;
  if (events_valid && !grid_valid) {
    in.inconsistent("events valid", "1", "pending events need the grid they were predicted in");
  }

  const std::uint32_t wall_count = in.u32("wall count");
  if (wall_count > in.remaining()) {
    in.inconsistent("wall count", std::to_string(wall_count), "more than the bytes that follow");
  }
  if (wall_count > detail::EventQueue::kMaxWalls) {
    in.inconsistent("wall count", std::to_string(wall_count), "more than a world holds (2^30)");
  }
  if (def.boundary == Boundary::periodic && wall_count != 0) {
    in.inconsistent("wall count", std::to_string(wall_count), "a periodic world has no walls");
  }
  if (def.boundary == Boundary::box && wall_count < 4) {
    in.inconsistent("wall count", std::to_string(wall_count), "a box has its four walls");
  }
  boundary_walls = def.boundary == Boundary::box ? 4 : 0;
  for (std::uint32_t w = 0; w < wall_count; ++w) {
    const std::uint8_t kind = in.u8("wall kind");
    if (kind > 2 || (kind == 2 && (flagged_version & kSensorsFlag) == 0)) {
      in.inconsistent("wall kind", std::to_string(kind),
                      "0 (segment), 1 (arc) or 2 (a sensor's disc)");
    }
    if (kind == 2) {
      Ball disc;
      disc.center = in.vec2("disc center");
      disc.radius = in.f64("disc radius");
      if (!finite(disc.center) || !std::isfinite(disc.radius) || !(disc.radius > 0.0)) {
        in.inconsistent("disc " + std::to_string(w),
                        vector_text(disc.center) + " " + number_text(disc.radius),
                        "a finite centre and a finite radius > 0");
      }
      walls.push_back(detail::make_disc_sensor(disc, detail::SensorRole::report));
    } else if (kind == 1) {
      Arc arc;
      arc.center = in.vec2("arc center");
      arc.radius = in.f64("arc radius");
      arc.start_angle = in.f64("arc start angle");
      arc.end_angle = in.f64("arc end angle");
      try {
        walls.push_back(detail::make_arc_wall("World::load", arc));  // validates the arc
      } catch (const InvalidArgument& e) {
        in.inconsistent("arc " + std::to_string(w), e.value(), e.requirement());
      }
    } else {
      Segment segment;
      segment.a = in.vec2("segment a");
      segment.b = in.vec2("segment b");
      if (!finite(segment.a) || !finite(segment.b)) {
        in.inconsistent("segment", vector_text(segment.a) + "-" + vector_text(segment.b),
                        "must be finite");
      }
      walls.push_back(detail::make_segment_wall(segment));
    }
  }

  const std::uint32_t slots = in.u32("ball slot count");
  if (slots > in.remaining() || slots > detail::EventQueue::kMaxBalls) {
    in.inconsistent("ball slot count", std::to_string(slots), "more than the bytes that follow");
  }
  const bool tc = def.collapse_time > 0.0;
  balls.resize(slots);
  infos.resize(slots);
  handle_of.resize(slots);
  slot_of_handle.resize(slots);
  for (std::uint32_t i = 0; i < slots; ++i) {
    handle_of[i] = i;  // stored in handle order (save_payload)
    slot_of_handle[i] = i;
  }
  if (tc) last_contact_times.resize(slots);
  if (gravity_on) carriages.resize(slots);
  double largest_alive = 0.0;
  for (std::uint32_t i = 0; i < slots; ++i) {
    detail::BallSlot& b = balls[i];
    detail::BallInfo& info = infos[i];
    const bool alive = in.u8("ball alive") != 0;
    b.position = in.vec2("ball position");
    b.velocity = in.vec2("ball velocity");
    b.local_time = in.f64("ball local time");
    const double radius = in.f64("ball radius");
    const double inverse_mass = in.f64("ball inverse mass");
    b.version = in.u32("ball version");
    const double mass = in.f64("ball mass");
    const double restitution = in.f64("ball restitution");
    info.user_data = in.u64("ball user data");
    info.generation = in.u32("ball generation");
    if (tc) last_contact_times[i] = in.f64("ball last contact time");
    const std::string which = "ball slot " + std::to_string(i);
    if (gravity_on) load_carriage(in, i, which);
    if (info.generation == 0) in.inconsistent(which, "generation 0", "0 is the null handle's");
    if (!alive) continue;
    ++live_count;
    largest_alive = std::max(largest_alive, radius);
    const bool immovable = mass == kImmovable;
    if (!finite(b.position) || !finite(b.velocity) || !(b.local_time <= time) ||
        !std::isfinite(b.local_time) || !(radius > 0.0 && std::isfinite(radius)) ||
        !(immovable ? inverse_mass == 0.0
                    : mass > 0.0 && std::isfinite(mass) && inverse_mass == 1.0 / mass) ||
        !(restitution >= 0.0 && restitution <= 1.0) || (tc && std::isnan(last_contact_times[i]))) {
      in.inconsistent(which, "position " + vector_text(b.position),
                      "a live ball has finite motion no later than the world's time, a positive "
                      "radius, a valid mass and restitution");
    }
    b.species = species.acquire(radius, mass, restitution);
    if (restitution != def.restitution) mixed_restitution = true;
  }
  if (!(largest_radius >= largest_alive && std::isfinite(largest_radius))) {
    in.inconsistent("largest radius", number_text(largest_radius),
                    "must be finite and no smaller than any live ball's");
  }
  const std::uint32_t free_count = in.u32("free slot count");
  if (free_count != slots - live_count) {
    in.inconsistent("free slot count", std::to_string(free_count),
                    "must equal the dead slots' count " + std::to_string(slots - live_count));
  }
  std::vector<bool> listed(slots, false);
  for (std::uint32_t k = 0; k < free_count; ++k) {
    const std::uint32_t slot = in.u32("free slot");
    if (slot >= slots || balls[slot].alive() || listed[slot]) {
      in.inconsistent("free slot", std::to_string(slot), "must name each dead slot once");
    }
    listed[slot] = true;
    free_handles.push_back(slot);
  }

  // Without a grid every ball stays in no cell (a new slot's), so remove_ball's erase has nothing
  // to do.
  if (grid_valid) load_grid(in);
  if (events_valid) {
    queue.reset(slots);
    queue.use_handles(handle_of.data());
    for (std::uint32_t i = 0; i < slots; ++i) {
      detail::Event event;
      event.owner = i;
      event.time = in.f64("event time");
      const std::uint8_t kind = in.u8("event kind");
      event.partner = in.u32("event partner");
      event.partner_version = in.u32("event partner version");
      const std::uint32_t partners =
          kind == 0 ? slots : (kind == 1 ? wall_count : (kind == 2 ? 4 : 1));
      if (kind > (accelerated ? 3 : 2) || event.partner >= partners ||
          (kind == 0 && event.partner == i) || std::isnan(event.time) ||
          event.time == -std::numeric_limits<double>::infinity()) {
        in.inconsistent("event of ball slot " + std::to_string(i), number_text(event.time),
                        "kind, partner or time out of range");
      }
      event.kind = static_cast<detail::EventKind>(kind);
      queue.set(i, event);
    }
  }
  if ((flagged_version & kFiltersFlag) != 0) load_filters(in);
  if ((flagged_version & kSensorsFlag) != 0) load_sensors(in);
  if ((flagged_version & kWallChangesFlag) != 0) load_wall_changes(in);
  if (table_on) load_table(in);
  if (in.remaining() != 0) {
    in.inconsistent("payload", std::to_string(in.remaining()) + " bytes", "left over at the end");
  }
}

// The filters' section: the table (at least the default and one more), each slot's number (by
// handle, as the slots are stored) and each wall's, every number within the table.
void World::Impl::load_filters(ByteReader& in) {
  const std::uint32_t count = in.u32("filter count");
  if (count < 2 || count > in.remaining() / 20) {
    in.inconsistent("filter count", std::to_string(count), "at least 2, and within the payload");
  }
  std::vector<CollisionFilter> table(count);
  for (CollisionFilter& f : table) {
    f.category = in.u64("filter category");
    f.mask = in.u64("filter mask");
    f.group = in.i32("filter group");
  }
  if (table.front() != CollisionFilter{}) {
    in.inconsistent("filter 0", "-", "must be the default filter");
  }
  filters.assign(std::move(table));
  const auto number = [&](const char* what) {
    const std::uint32_t k = in.u32(what);
    if (k >= count) in.inconsistent(what, std::to_string(k), "not a filter of the table");
    return k;
  };
  for (std::uint32_t i = 0; i < balls.size(); ++i) infos[i].filter = number("ball filter");
  for (detail::Wall& wall : walls) wall.filter = number("wall filter");
}

// The sensors' section: each wall's role (a disc must be a sensor), then the pairs recorded
// inside, ascending, each naming a live ball's handle and a sensor.
void World::Impl::load_sensors(ByteReader& in) {
  for (detail::Wall& wall : walls) {
    const std::uint8_t role = in.u8("sensor role");
    if (role > 2 || (wall.is_disc && role == 0)) {
      in.inconsistent("sensor role", std::to_string(role),
                      "0 (a wall), 1 (report) or 2 (remove the ball); a disc is a sensor");
    }
    wall.sensor = static_cast<detail::SensorRole>(role);
  }
  const std::uint64_t count = in.u64("sensor pair count");
  if (count > in.remaining() / 8) {
    in.inconsistent("sensor pair count", std::to_string(count), "more than the bytes that follow");
  }
  std::uint64_t previous = 0;
  for (std::uint64_t k = 0; k < count; ++k) {
    const std::uint64_t key = in.u64("sensor pair");
    const auto handle = static_cast<std::uint32_t>(key >> 32);
    const auto wall = static_cast<std::uint32_t>(key & 0xffffffffU);
    const bool named = handle < slot_of_handle.size() && balls[slot_of_handle[handle]].alive() &&
                       wall < walls.size() && walls[wall].sensor != detail::SensorRole::none;
    if (!named || (k > 0 && key <= previous)) {
      in.inconsistent("sensor pair", std::to_string(handle) + ", " + std::to_string(wall),
                      "a live ball and a sensor, in ascending order");
    }
    sensor_inside.insert(sensor_inside.end(), key);
    previous = key;
  }
}

// The moving and removed walls' section: ascending ids of walls that may change (no side of a
// box; a moving wall a segment or an arc that is no sensor), finite paths that start no later than
// they end. Each moving wall's shape is then brought to the world's time, as it was when saved.
// The table's section: its definition (validated as World's constructor does) and each slot's
// spin and state, by handle.
void World::Impl::load_table(ByteReader& in) {
  Table table;
  table.g = in.f64("table g");
  table.sliding_friction = in.f64("table sliding friction");
  table.rolling_friction = in.f64("table rolling friction");
  table.spinning_friction = in.f64("table spinning friction");
  table.ball_friction = in.f64("table ball friction");
  table.cushion_height = in.f64("table cushion height");
  table.cushion_restitution = in.f64("table cushion restitution");
  table.cushion_friction = in.f64("table cushion friction");
  table.contact_time = in.f64("table contact time");
  try {
    WorldDef check;
    check.table = table;
    const World validated(check);
  } catch (const InvalidArgument& e) {
    in.inconsistent(e.argument(), e.value(), e.requirement());
  }
  def.table = table;
  use_table();
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    detail::TableSlot& slot = table_slots[i];
    slot.spin = in.vec2("ball spin");
    slot.twist = in.f64("ball twist");
    slot.acceleration = in.vec2("ball table acceleration");
    slot.ends = in.f64("ball state end");
    const std::uint8_t state = in.u8("ball motion state");
    const bool bad_state = state > static_cast<std::uint8_t>(detail::TableState::stationary);
    // (A free slot keeps what its last ball left, so that it saves again to the same bytes.)
    if (bad_state || (balls[i].alive() && (!finite(slot.spin) || !std::isfinite(slot.twist) ||
                                           !finite(slot.acceleration) || std::isnan(slot.ends)))) {
      in.inconsistent("table state of ball slot " + std::to_string(i), std::to_string(state),
                      "a motion state (0 to 3) with finite spin and acceleration");
    }
    slot.state = static_cast<detail::TableState>(state);
  }
}

void World::Impl::load_wall_changes(ByteReader& in) {
  const std::uint32_t count = in.u32("changed wall count");
  if (count > walls.size()) {
    in.inconsistent("changed wall count", std::to_string(count), "more than the walls");
  }
  std::uint32_t previous = 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t w = in.u32("changed wall");
    const bool box_side = def.boundary == Boundary::box && w < 4;
    if (w >= walls.size() || box_side || (k > 0 && w <= previous)) {
      in.inconsistent("changed wall", std::to_string(w),
                      "a wall that may change (no side of the box), in ascending order");
    }
    previous = w;
    detail::Wall& wall = walls[w];
    const std::uint8_t removed = in.u8("wall removed");
    const std::uint8_t moving = in.u8("wall moving");
    if (removed > 1 || moving > 1 || (removed == 0 && moving == 0) ||
        (moving == 1 && (wall.is_disc || wall.sensor != detail::SensorRole::none))) {
      in.inconsistent("changed wall " + std::to_string(w),
                      std::to_string(removed) + ", " + std::to_string(moving),
                      "removed or moving (0 or 1, not both 0); only a solid segment or arc moves");
    }
    wall.removed = removed == 1;
    wall.moving = moving == 1;
    if (!wall.moving) continue;
    detail::WallPath& path = wall.path;
    path.rigid.velocity = in.vec2("wall path velocity");
    path.rigid.angular_velocity = in.f64("wall path angular velocity");
    path.rigid.pivot = in.vec2("wall path pivot");
    path.start = in.f64("wall path start");
    path.until = in.f64("wall path end");
    bool shape_valid = true;
    if (wall.is_arc) {
      path.arc.center = in.vec2("wall path arc");
      path.arc.radius = in.f64("wall path arc");
      path.arc.start_angle = in.f64("wall path arc");
      path.arc.end_angle = in.f64("wall path arc");
      path.frame.center = in.vec2("wall path arc frame");
      path.frame.radius = in.f64("wall path arc frame");
      path.frame.span = in.f64("wall path arc frame");
      path.frame.start_direction = in.vec2("wall path arc frame");
      path.frame.end_direction = in.vec2("wall path arc frame");
      path.frame.start_point = in.vec2("wall path arc frame");
      path.frame.end_point = in.vec2("wall path arc frame");
      const detail::ArcFrame& f = path.frame;
      shape_valid = finite(path.arc.center) && std::isfinite(path.arc.radius) &&
                    path.arc.radius > 0.0 && std::isfinite(path.arc.start_angle) &&
                    std::isfinite(path.arc.end_angle) && finite(f.center) && f.radius > 0.0 &&
                    std::isfinite(f.radius) && f.span >= 0.0 && f.span <= 2.0 * std::numbers::pi &&
                    finite(f.start_direction) && finite(f.end_direction) && finite(f.start_point) &&
                    finite(f.end_point);
    } else {
      path.segment.a = in.vec2("wall path segment");
      path.segment.b = in.vec2("wall path segment");
      shape_valid = finite(path.segment.a) && finite(path.segment.b);
    }
    if (!shape_valid || !finite(path.rigid.velocity) ||
        !std::isfinite(path.rigid.angular_velocity) || !finite(path.rigid.pivot) ||
        !std::isfinite(path.start) || std::isnan(path.until) || path.until < path.start) {
      in.inconsistent("wall path " + std::to_string(w), number_text(path.start),
                      "finite motion, pivot and shape, starting no later than it ends");
    }
    path.reach = detail::path_reach(wall);
    path.speed = length(path.rigid.velocity);
    moving_walls.push_back(w);
    detail::place_at(wall, time);
  }
  if (grid_valid) list_walls();
}

// A slot's carriage (version 3), checked for what it names: walls that exist, handles within the
// slots, finite values. (That a support touches its ball is physics: audit() tells.)
void World::Impl::load_carriage(ByteReader& in, std::uint32_t slot, const std::string& which) {
  detail::Carriage& c = carriages[slot];
  const std::uint8_t state = in.u8("ball carriage state");
  c.supports = in.u8("ball carriage supports");
  c.support[0] = in.u32("ball carriage support");
  c.support[1] = in.u32("ball carriage support");
  c.acceleration = in.vec2("ball carriage acceleration");
  c.normal = in.vec2("ball carriage normal");
  c.origin = in.vec2("ball carriage origin");
  c.lower = in.f64("ball carriage lower");
  c.upper = in.f64("ball carriage upper");
  c.state = static_cast<detail::Carried>(state);
  const auto names_something = [&](std::uint32_t key) {
    if ((key & detail::kBallSupport) != 0) {
      return (key & ~detail::kBallSupport) < carriages.size() &&
             (key & ~detail::kBallSupport) != slot;
    }
    return key < walls.size();
  };
  const bool supports_valid = c.supports <= 2 &&
                              (c.supports < 1 || names_something(c.support[0])) &&
                              (c.supports < 2 || names_something(c.support[1]));
  const bool state_valid = state <= static_cast<std::uint8_t>(detail::Carried::resting) &&
                           (state == 0) == (c.supports == 0);
  if (!supports_valid || !state_valid || !finite(c.acceleration) || !finite(c.normal) ||
      !finite(c.origin) || std::isnan(c.lower) || std::isnan(c.upper)) {
    in.inconsistent(which, "carriage state " + std::to_string(state),
                    "a carriage is free, sliding or resting, on walls and balls that exist, with "
                    "finite values");
  }
}

void World::Impl::load_grid(ByteReader& in) {
  const Vec2 lower = in.vec2("grid lower");
  const Vec2 cell = in.vec2("grid cell size");
  const Vec2 hysteresis = in.vec2("grid hysteresis");
  const std::int32_t nx = in.i32("grid columns");
  const std::int32_t ny = in.i32("grid rows");
  const auto slots = static_cast<std::uint32_t>(balls.size());
  // A grid never has more cells than wanted_cell_size allows (4 a ball, at least 1024), give or
  // take the rounding of the cell count; this bound keeps a damaged file from allocating more.
  const double most_cells = 2.0 * std::max(1024.0, 4.0 * (static_cast<double>(slots) + 1.0)) + 9;
  // The grid of an open world with no ball (nor a wall of any extent) has cells of size 0: the
  // engine plans cells from the largest radius and the extent, both 0. It is harmless there (the
  // next add_ball finds the cell too small and re-plans) and must load like any state save wrote.
  const bool cells_fit =
      (cell.x > 0.0 && cell.y > 0.0) || (live_count == 0 && cell.x >= 0.0 && cell.y >= 0.0);
  if (!finite(lower) || !finite(cell) || !cells_fit || nx < 1 || ny < 1 ||
      static_cast<double>(nx) * static_cast<double>(ny) > most_cells) {
    in.inconsistent("grid", std::to_string(nx) + "x" + std::to_string(ny),
                    "a grid has finite positive cells (or none if no ball) and at most " +
                        carom::number_text(most_cells) + " of them");
  }
  // The engine gives the hysteresis part of the room a cell has beyond the largest diameter, at
  // most a tenth of the cell.
  const bool sized = hysteresis.x >= 0.0 && hysteresis.x <= detail::kMostHysteresis * cell.x &&
                     hysteresis.y >= 0.0 && hysteresis.y <= detail::kMostHysteresis * cell.y;
  if (!finite(hysteresis) || !sized) {
    in.inconsistent("grid hysteresis", detail::vector_text(hysteresis),
                    "a cell's hysteresis is at least 0 and at most a tenth of the cell");
  }
  grid.setup(lower, cell, nx, ny, def.boundary == Boundary::periodic, def.boundary == Boundary::box,
             hysteresis);
  const std::int32_t cells = nx * ny;
  std::vector<std::int32_t> cell_of(slots);
  for (std::uint32_t i = 0; i < slots; ++i) {
    cell_of[i] = in.i32("ball cell");
    const bool fits = balls[i].alive() ? cell_of[i] >= 0 && cell_of[i] < cells : cell_of[i] == -1;
    if (!fits) {
      in.inconsistent("cell of ball slot " + std::to_string(i), std::to_string(cell_of[i]),
                      "a live ball lies in a grid cell, a dead one in none");
    }
  }
  // The cells' lists, walked in cell order: reinserted backwards, since insert puts a ball first.
  std::vector<std::uint32_t> order(live_count);
  std::vector<bool> seen(slots, false);
  for (std::size_t k = 0; k < live_count; ++k) {
    order[k] = in.u32("grid order");
    const std::uint32_t ball = order[k];
    if (ball >= slots || !balls[ball].alive() || seen[ball] ||
        (k > 0 && cell_of[ball] < cell_of[order[k - 1]])) {
      in.inconsistent("grid order", std::to_string(ball), "must list each live ball once, by cell");
    }
    seen[ball] = true;
  }
  for (std::size_t k = order.size(); k-- > 0;) grid.insert(order[k], cell_of[order[k]]);
  list_walls();
}

World World::load(std::istream& in) {
  constexpr const char* kFunction = "World::load";
  std::uint32_t version = 0;
  const std::string payload = read_payload(kFunction, "in", in, version);
  ByteReader reader(kFunction, payload);
  World world;
  world.impl_->load_payload(reader, version);
  return world;
}

World World::load(const std::filesystem::path& path) {
  constexpr const char* kFunction = "World::load";
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InvalidArgument(kFunction, "path", path.string(),
                          std::string("cannot open it: ") + std::strerror(errno));
  }
  std::uint32_t version = 0;
  const std::string payload = read_payload(kFunction, "path " + path.string(), in, version);
  ByteReader reader(kFunction, payload);
  World world;
  world.impl_->load_payload(reader, version);
  return world;
}

}  // namespace carom
