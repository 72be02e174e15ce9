// The reference scenes' results, bit for bit: each example scene (and an inelastic gas with
// collapse prevention and moving posts) is run by steps and then by contacts, and a hash of every
// contact (time, kind, balls, wall, point, normal, approach speed, impulse) and of the final state
// (every ball's position and velocity, the time) is compared with the hash recorded here. A change
// that is meant to keep results (a refactoring, a new feature switched off) keeps every hash; one
// that changes results on purpose says so and records the new hashes.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "carom/scene.hpp"

namespace carom {
namespace {

// FNV-1a over the bit patterns of the numbers: any difference in any bit changes it.
class Hash {
 public:
  void add(std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
      value_ ^= (word >> (8 * byte)) & 0xffU;
      value_ *= 1099511628211ULL;
    }
  }
  void add(double x) { add(std::bit_cast<std::uint64_t>(x)); }
  void add(Vec2 v) {
    add(v.x);
    add(v.y);
  }
  [[nodiscard]] std::uint64_t value() const { return value_; }

 private:
  std::uint64_t value_ = 14695981039346656037ULL;
};

void add_contacts(Hash& hash, const std::vector<ContactEvent>& contacts) {
  for (const ContactEvent& c : contacts) {
    hash.add(c.time);
    hash.add(static_cast<std::uint64_t>(c.kind));
    hash.add((std::uint64_t{c.a.index} << 32U) | c.a.generation);
    hash.add((std::uint64_t{c.b.index} << 32U) | c.b.generation);
    hash.add(std::uint64_t{c.wall});
    hash.add(c.point);
    hash.add(c.normal);
    hash.add(c.approach_speed);
    hash.add(c.impulse);
  }
}

void add_state(Hash& hash, const SceneWorld& built) {
  hash.add(built.world.time());
  hash.add(built.world.collision_count());
  for (const BallId id : built.world.balls()) {
    hash.add(built.world.position(id));
    hash.add(built.world.velocity(id));
  }
}

// `steps` steps of `dt`, then `contacts` contacts (bounded in time, for open scenes whose balls
// part for good).
std::uint64_t run_hash(const Scene& scene, int steps, double dt, std::uint64_t contacts) {
  SceneWorld built = make_world(scene);
  Hash hash;
  std::vector<ContactEvent> seen;
  for (int k = 0; k < steps; ++k) {
    seen.clear();
    static_cast<void>(step_scene(built, dt, &seen));
    add_contacts(hash, seen);
  }
  add_state(hash, built);
  seen.clear();
  const double limit = built.world.time() + 100.0 * dt * steps;
  static_cast<void>(run_scene_collisions(built, contacts, &seen, nullptr, limit));
  add_contacts(hash, seen);
  add_state(hash, built);
  return hash.value();
}

// Inelastic balls (e = 0.6 and 0.9) with collapse prevention, moving immovable posts, an arc and
// a segment in a box: the paths that the examples leave out.
constexpr const char* kInelasticBox = R"({
  "carom_scene": 1,
  "world": {"boundary": "box", "lower": [0, 0], "upper": [30, 20], "restitution": 0.6,
            "collapse_time": 0.01},
  "segments": [{"a": [5, 15], "b": [12, 17]}],
  "arcs": [{"center": [22, 10], "radius": 4, "start_angle": 1, "end_angle": 4}],
  "balls": [
    {"position": [3, 3], "velocity": [0.4, 0], "radius": 0.8, "mass": "immovable"},
    {"position": [27, 3], "velocity": [0, 0.3], "radius": 0.8, "mass": "immovable"}
  ],
  "generators": [
    {"count": 120, "region": {"lower": [2, 6], "upper": [16, 13]}, "radius": 0.4,
     "restitution": 0.9, "velocity": {"distribution": "maxwell_boltzmann", "temperature": 2},
     "seed": 7}
  ]
})";
struct Reference {
  const char* name;
  int steps;
  double dt;
  std::uint64_t contacts;
  std::uint64_t hash;
};

Scene reference_scene(const std::string& name) {
  if (name == "inelastic-box") return parse_scene(kInelasticBox, name);
  return load_scene(std::string(CAROM_EXAMPLES_DIR) + "/" + name + ".json");
}

class ReferenceHash : public ::testing::TestWithParam<Reference> {};

TEST_P(ReferenceHash, TheContactsAndTheEndAreBitIdentical) {
  const Reference& r = GetParam();
  const std::uint64_t hash = run_hash(reference_scene(r.name), r.steps, r.dt, r.contacts);
  char text[32];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash));
  EXPECT_EQ(hash, r.hash) << r.name << " now hashes to " << text
                          << "; if the change is meant to change results, record it here";
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ReferenceHash,
    ::testing::Values(Reference{"billiards-frictionless", 40, 0.05, 200, 0x73deb09f8b73fde6ULL},
                      Reference{"box-of-1000", 20, 0.1, 5000, 0xf778b9e92d9eea05ULL},
                      Reference{"newtons-cradle", 20, 0.5, 50, 0x2a7c03d4d0b97c12ULL},
                      Reference{"periodic-gas", 2, 0.01, 20000, 0x94148229afe4e581ULL},
                      Reference{"pinball", 40, 0.05, 200, 0x50553f8b23671964ULL},
                      Reference{"two-moving-balls", 4, 0.25, 5, 0x90c91ddf7e46df08ULL},
                      Reference{"inelastic-box", 40, 0.05, 3000, 0x02e599e92a3baa16ULL}),
    [](const ::testing::TestParamInfo<Reference>& scene_info) {
      std::string name = scene_info.param.name;
      for (char& c : name) {
        if (c == '-') c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace carom
