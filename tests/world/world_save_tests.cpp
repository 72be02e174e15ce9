// World::save and World::load (include/carom/world.hpp; format in docs/world.md, "Saving and
// resuming"): a run saved and resumed at any point between calls is bit-identical to the same
// run uninterrupted, and a damaged save is refused with a message that says what is wrong.
#include <gtest/gtest.h>
#include <unistd.h>  // getpid: a folder of its own for the file test

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"
#include "world/random_scene.hpp"
#include "world/scene_world.hpp"

namespace carom {
namespace {

// The format's fixed layout (docs/world.md): magic 8, version 4, payload size 8, checksum 8.
constexpr std::size_t kVersionAt = 8;
constexpr std::size_t kSizeAt = 12;
constexpr std::size_t kChecksumAt = 20;
constexpr std::size_t kPayloadAt = 28;
// The payload opens with the WorldDef: boundary (1 byte), lower, upper (16 each), restitution,
// collapse_time, cell_size (8 each); the world's time follows.
constexpr std::size_t kTimeAt = kPayloadAt + 1 + 16 + 16 + 8 + 8 + 8;

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

// Everything observable, bit for bit, as one list of words (so that a difference is one index).
using Trace = std::vector<std::uint64_t>;

void append_contacts(const World& world, Trace& trace) {
  for (const ContactEvent& c : world.contacts()) {
    trace.insert(trace.end(),
                 {bits(c.time), static_cast<std::uint64_t>(c.kind), c.a.index, c.a.generation,
                  c.b.index, c.b.generation, c.wall, bits(c.point.x), bits(c.point.y),
                  bits(c.normal.x), bits(c.normal.y), bits(c.approach_speed), bits(c.impulse)});
  }
}

void append_state(const World& world, Trace& trace) {
  trace.insert(trace.end(), {bits(world.time()), world.collision_count(), world.ball_count(),
                             world.wall_count(), world.contact_recording() ? 1U : 0U});
  for (const BallId id : world.balls()) {
    const Vec2 p = world.position(id);
    const Vec2 v = world.velocity(id);
    trace.insert(trace.end(), {id.index, id.generation, bits(p.x), bits(p.y), bits(v.x), bits(v.y),
                               bits(world.radius(id)), bits(world.mass(id)), world.user_data(id)});
  }
}

World reload(const World& world) {
  std::stringstream file(std::ios::in | std::ios::out | std::ios::binary);
  world.save(file);
  return World::load(file);
}

// One call (or a few) on the world; what it returns, and the contacts of a call that advances
// time, go into the trace (contacts() holds the last such call's, and a loaded world has none).
using Operation = std::function<void(World&, Trace&)>;

// Applies the operations in order, saving and reloading the world before each operation whose
// index is in `save_before`; the trace holds every contact, result and the state after each.
Trace run(World world, const std::vector<Operation>& operations,
          const std::set<std::size_t>& save_before) {
  Trace trace;
  for (std::size_t k = 0; k < operations.size(); ++k) {
    if (save_before.contains(k)) world = reload(world);
    operations[k](world, trace);
    append_state(world, trace);
  }
  return trace;
}

::testing::AssertionResult identical(const Trace& resumed, const Trace& uninterrupted) {
  for (std::size_t i = 0; i < std::min(resumed.size(), uninterrupted.size()); ++i) {
    if (resumed[i] != uninterrupted[i]) {
      return ::testing::AssertionFailure()
             << "first difference at word " << i << " of " << uninterrupted.size() << ": "
             << resumed[i] << " resumed, " << uninterrupted[i] << " uninterrupted";
    }
  }
  if (resumed.size() != uninterrupted.size()) {
    return ::testing::AssertionFailure()
           << resumed.size() << " words resumed, " << uninterrupted.size() << " uninterrupted";
  }
  return ::testing::AssertionSuccess();
}

Operation collisions(std::uint64_t count) {
  return [count](World& w, Trace& t) {
    t.push_back(w.run_collisions(count));
    append_contacts(w, t);
  };
}
Operation collisions_until(std::uint64_t count, double span) {
  return [count, span](World& w, Trace& t) {
    t.push_back(w.run_collisions(count, w.time() + span));
    append_contacts(w, t);
  };
}
Operation step(double dt) {
  return [dt](World& w, Trace& t) {
    t.push_back(bits(w.step(dt)));
    append_contacts(w, t);
  };
}
// A long step ended early by a stop condition after `contacts` contacts (the condition is not
// saved, so the operation sets it each time, as a resuming program would).
Operation stopped_step(int contacts) {
  return [contacts](World& w, Trace& t) {
    int seen = 0;
    w.set_stop_condition([&seen, contacts](const ContactEvent&) { return ++seen == contacts; });
    t.push_back(bits(w.step(1e6)));
    t.push_back(w.stopped_early() ? 1U : 0U);
    append_contacts(w, t);
    w.set_stop_condition(nullptr);
  };
}

// Every single save point, and a few together, against the run without any.
void expect_resumes_bit_identical(const std::function<World()>& build,
                                  const std::vector<Operation>& operations,
                                  std::uint64_t min_collisions) {
  const Trace uninterrupted = run(build(), operations, {});
  std::set<std::size_t> all;
  for (std::size_t k = 0; k < operations.size(); ++k) {
    EXPECT_TRUE(identical(run(build(), operations, {k}), uninterrupted)) << "saved before op " << k;
    all.insert(k);
  }
  EXPECT_TRUE(identical(run(build(), operations, all), uninterrupted)) << "saved before every op";
  World world = build();
  for (const Operation& op : operations) {
    Trace ignored;
    op(world, ignored);
  }
  EXPECT_GE(world.collision_count(), min_collisions);  // the run really did collide this often
}

// A gas long enough for the engine to re-order its balls by grid cell (over 2^16 events,
// engine_tuning.hpp's kSortMinEvents) a few times. A loaded world stores its balls in handle
// order, so every resumed run below continues from a different memory order than the
// uninterrupted one, at other re-order points: the traces agree only if storage order changes
// no result.
World reordered_gas() {
  testing::GasOptions options;
  options.ball_count = 400;
  options.side = 30.0;
  options.periodic = true;
  return std::move(testing::build_world(testing::random_gas(options, 11)).world);
}

TEST(WorldSave, ReorderingBallsInMemoryChangesNoResult) {
  const std::vector<Operation> operations = {collisions(30000), collisions(25000), step(0.5),
                                             collisions(30000)};
  expect_resumes_bit_identical(reordered_gas, operations, 85000);
}

World periodic_gas() {
  testing::GasOptions options;
  options.ball_count = 300;
  options.side = 40.0;
  options.periodic = true;
  return std::move(testing::build_world(testing::random_gas(options, 7)).world);
}

TEST(WorldSave, PeriodicGasResumesBitIdentical) {
  const std::vector<Operation> operations = {collisions(1500),  collisions(1),
                                             step(0.37),        collisions(1200),
                                             stopped_step(333), collisions_until(1500, 2.0),
                                             collisions(900)};
  expect_resumes_bit_identical(periodic_gas, operations, 4000);
}

// A box with an arc and a segment inside, inelastic balls with collapse prevention on, a resting
// post, and handles recycled around the save points.
World inelastic_box() {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {40.0, 40.0};
  def.restitution = 0.8;
  def.collapse_time = 0.05;
  World world(def);
  world.add_arc(Arc{{20.0, 20.0}, 4.0, 0.3, 4.5});
  world.add_segment(Segment{{5.0, 30.0}, {15.0, 35.0}});
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 16; ++i) {
    for (int j = 0; j < 16; ++j) {
      BallDef ball;
      ball.position = {1.25 + 2.5 * i + 0.3 * unit(random), 1.25 + 2.5 * j + 0.3 * unit(random)};
      ball.velocity = {6.0 * unit(random) - 3.0, 6.0 * unit(random) - 3.0};
      ball.radius = 0.35 + 0.4 * unit(random);
      ball.mass = (i * 16 + j) % 97 == 5 ? kImmovable : 0.5 + unit(random);
      if (j % 3 == 0) ball.restitution = 0.5;
      ball.user_data = static_cast<std::uint64_t>(1000 + i * 16 + j);
      try {
        world.add_ball(ball);
      } catch (const InvalidArgument&) {
        // That place overlaps the arc or the segment: leave it empty.
      }
    }
  }
  return world;
}

TEST(WorldSave, InelasticBoxWithArcsResumesBitIdentical) {
  auto removed = std::make_shared<std::vector<BallDef>>();
  const Operation remove_two = [removed](World& w, Trace&) {
    removed->clear();
    for (const std::size_t k : {3U, 40U}) {
      const BallId id = w.balls()[k];
      BallDef def;
      def.position = w.position(id);
      def.radius = w.radius(id);
      def.user_data = 77;
      removed->push_back(def);
      w.remove_ball(id);
    }
  };
  // Adds the first removed ball back: the slot is the last freed one, with its next generation.
  const Operation add_back = [removed](World& w, Trace& t) {
    const BallId id = w.add_ball(removed->front());
    t.insert(t.end(), {id.index, id.generation});
  };
  const std::vector<Operation> operations = {collisions(1200),
                                             remove_two,
                                             add_back,
                                             collisions(1500),
                                             step(0.05),
                                             stopped_step(250),
                                             collisions_until(1000, 3.0),
                                             collisions(1000)};
  expect_resumes_bit_identical(inelastic_box, operations, 4000);
}

// Adding a wall drops the grid until the next run: a world saved then has balls but no grid,
// and removing one of them after load must still work (and match).
TEST(WorldSave, AWorldSavedWithoutItsGridResumes) {
  const auto build = [] {
    World world = inelastic_box();
    world.run_collisions(100);
    world.add_segment(Segment{{30.0, 5.0}, {30.0, 5.5}});
    return world;
  };
  const Operation remove_first = [](World& w, Trace&) { w.remove_ball(w.balls().front()); };
  const std::vector<Operation> operations = {remove_first, collisions(300)};
  const Trace uninterrupted = run(build(), operations, {});
  EXPECT_TRUE(identical(run(build(), operations, {0}), uninterrupted));
}

TEST(WorldSave, SavingALoadedWorldGivesTheSameBytes) {
  World world = inelastic_box();
  world.run_collisions(500);
  std::ostringstream first(std::ios::binary);
  world.save(first);
  std::istringstream in(first.str(), std::ios::binary);
  const World loaded = World::load(in);
  std::ostringstream second(std::ios::binary);
  loaded.save(second);
  EXPECT_EQ(first.str(), second.str());
}

TEST(WorldSave, LoadReadsOneSaveFromAStream) {
  World world = periodic_gas();
  std::stringstream file(std::ios::in | std::ios::out | std::ios::binary);
  world.save(file);
  world.run_collisions(100);
  world.save(file);
  EXPECT_EQ(World::load(file).collision_count(), 0U);
  EXPECT_EQ(World::load(file).collision_count(), 100U);
}

TEST(WorldSave, ContactsAndStopConditionAreNotSaved) {
  World world = periodic_gas();
  world.set_stop_condition([](const ContactEvent&) { return true; });
  ASSERT_EQ(world.run_collisions(10), 1U);
  ASSERT_FALSE(world.contacts().empty());
  ASSERT_TRUE(world.stopped_early());
  World loaded = reload(world);
  EXPECT_TRUE(loaded.contacts().empty());
  EXPECT_FALSE(loaded.stopped_early());
  EXPECT_EQ(loaded.run_collisions(10), 10U);  // no stop condition came along
}

// ---- damaged saves ---------------------------------------------------------------------------

std::string saved_bytes() {
  World world = inelastic_box();
  world.run_collisions(200);
  std::ostringstream out(std::ios::binary);
  world.save(out);
  return out.str();
}

void put_u64(std::string& bytes, std::size_t at, std::uint64_t value) {
  for (std::size_t i = 0; i < 8; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xffU);
}

// FNV-1a 64, written out again from its definition so that the test does not trust the library's.
std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  }
  return hash;
}

// Makes the header agree with a changed payload, so that only the content is wrong.
void reseal(std::string& bytes) {
  put_u64(bytes, kSizeAt, bytes.size() - kPayloadAt);
  put_u64(bytes, kChecksumAt, fnv1a64(std::string_view(bytes).substr(kPayloadAt)));
}

void expect_refused(const std::string& bytes, std::string_view why) {
  std::istringstream in(bytes, std::ios::binary);
  try {
    (void)World::load(in);
    ADD_FAILURE() << "loaded; expected carom::InvalidArgument saying " << why;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string_view(e.what()).find(why), std::string_view::npos)
        << "message: " << e.what() << "\nexpected: " << why;
  }
}

TEST(WorldSave, TheUntouchedSaveLoads) {
  std::istringstream in(saved_bytes(), std::ios::binary);
  EXPECT_EQ(World::load(in).collision_count(), 200U);
}

TEST(WorldSave, BadMagicIsRefused) {
  std::string bytes = saved_bytes();
  bytes[0] = 'X';
  expect_refused(bytes, "bad magic");
  expect_refused("", "bad magic");
  expect_refused("{\"balls\": []}", "bad magic");
}

TEST(WorldSave, UnsupportedVersionIsRefused) {
  std::string bytes = saved_bytes();
  bytes[kVersionAt] = 99;
  expect_refused(bytes, "unsupported version");
}

TEST(WorldSave, TruncationIsRefused) {
  const std::string bytes = saved_bytes();
  for (const std::size_t length :
       {std::size_t{10}, kPayloadAt - 1, kPayloadAt, kPayloadAt + 100, bytes.size() - 1}) {
    expect_refused(bytes.substr(0, length), "truncated");
  }
}

TEST(WorldSave, ChecksumMismatchIsRefused) {
  const std::string bytes = saved_bytes();
  for (const std::size_t at : {kPayloadAt, kTimeAt + 3, bytes.size() / 2, bytes.size() - 1}) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    expect_refused(damaged, "checksum mismatch");
  }
  std::string damaged = bytes;
  damaged[kChecksumAt] = static_cast<char>(damaged[kChecksumAt] ^ 1);
  expect_refused(damaged, "checksum mismatch");
}

TEST(WorldSave, InconsistentContentIsRefused) {
  const std::string bytes = saved_bytes();
  std::string boundary = bytes;
  boundary[kPayloadAt] = 7;
  reseal(boundary);
  expect_refused(boundary, "def.boundary = 7: inconsistent content");

  std::string time = bytes;
  put_u64(time, kTimeAt, bits(std::numeric_limits<double>::quiet_NaN()));
  reseal(time);
  expect_refused(time, "time = nan: inconsistent content");

  // After the def and time: collision count, largest radius (8 each), three flags, wall count
  // (4), the box's four segments (1 + 32 each), then the arc's kind (1) and centre (16).
  constexpr std::size_t kArcRadiusAt = kTimeAt + 8 + 8 + 8 + 3 + 4 + 4 * 33 + 1 + 16;
  std::string arc = bytes;
  put_u64(arc, kArcRadiusAt, bits(-1.0));
  reseal(arc);
  expect_refused(arc, "arc 4 = ");

  std::string longer = bytes + "more";
  reseal(longer);
  expect_refused(longer, "left over at the end");

  std::string shorter = bytes.substr(0, bytes.size() - 4);
  reseal(shorter);
  expect_refused(shorter, "inconsistent content");
}

// Any single changed byte with the header resealed: load refuses it cleanly or builds a world,
// never anything else (under the asan preset, never a bad memory access either).
TEST(WorldSave, ResealedRandomDamageIsRefusedOrLoaded) {
  const std::string bytes = saved_bytes();
  std::mt19937_64 random(3);
  std::uniform_int_distribution<std::size_t> where(kPayloadAt, bytes.size() - 1);
  std::uniform_int_distribution<int> value(0, 255);
  int refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::string damaged = bytes;
    damaged[where(random)] = static_cast<char>(value(random));
    reseal(damaged);
    std::istringstream in(damaged, std::ios::binary);
    try {
      const World world = World::load(in);
      EXPECT_LE(world.ball_count(), 256U);
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string_view(e.what()).find("inconsistent content"), std::string_view::npos)
          << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, 0);  // counts, indices and flags were hit, not only free-form doubles
}

// ---- files -----------------------------------------------------------------------------------

TEST(WorldSave, SavesAtomicallyToAPathAndLoadsBack) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("carom_save_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / "world.carom";
  World world = inelastic_box();
  world.run_collisions(300);
  world.save(path);
  world.run_collisions(300);
  world.save(path);  // replaces the first
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++files;
  EXPECT_EQ(files, 1U) << "a temporary file was left behind";
  World loaded = World::load(path);
  EXPECT_EQ(loaded.collision_count(), 600U);
  Trace original;
  Trace resumed;
  world.run_collisions(400);
  loaded.run_collisions(400);
  append_state(world, original);
  append_state(loaded, resumed);
  EXPECT_TRUE(identical(resumed, original));

  try {
    world.save(folder / "missing" / "world.carom");
    ADD_FAILURE() << "saved into a folder that does not exist";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string_view(e.what()).find("missing"), std::string_view::npos) << e.what();
  }
  try {
    (void)World::load(folder / "absent.carom");
    ADD_FAILURE() << "loaded a file that does not exist";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string_view(e.what()).find("absent.carom"), std::string_view::npos) << e.what();
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace carom
