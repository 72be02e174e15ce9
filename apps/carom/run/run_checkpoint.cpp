#include "run/run_checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "carom/atomic_file.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {
namespace {

constexpr std::string_view kMagic = "CAROMCKP";
// Version 2 added the time limit and the step in progress, version 3 the potential energy at the
// start; older files read as having none of what came after them. Version 4 names the pockets by
// their sensors' wall ids (they were immovable balls): older files, whose worlds hold pocket
// balls, cannot be continued. Version 5 adds the shots struck (a table's); version 4 files had
// none.
constexpr std::uint32_t kVersion = 5;
constexpr std::uint32_t kOldestVersion = 4;
// magic, version, content size, checksum.
constexpr std::size_t kHeaderSize = 8 + 4 + 8 + 8;

// FNV-1a, 64 bits: a damaged byte anywhere changes it; this guards against damage, not attack.
std::uint64_t checksum(std::string_view bytes) {
  std::uint64_t hash = 14695981039346656037ULL;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return hash;
}

// Numbers are stored as their bytes in memory: a checkpoint is read by the same build that wrote
// it (the same promise as World::save).
class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::array<char, sizeof(T)> bytes{};
    std::memcpy(bytes.data(), &value, sizeof(T));
    out_.append(bytes.data(), bytes.size());
  }
  void put_text(std::string_view text) {
    put<std::uint64_t>(text.size());
    out_.append(text);
  }
  void put_id(BallId id) {
    put(id.index);
    put(id.generation);
  }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

class Reader {
 public:
  Reader(std::string_view bytes, const std::string& file) : in_(bytes), file_(file) {}

  template <class T>
  T get(const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), what);
    T value{};
    std::memcpy(&value, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string_view get_text(const char* what) {
    const auto size = get<std::uint64_t>(what);
    need(size, what);
    const std::string_view text = in_.substr(at_, size);
    at_ += size;
    return text;
  }
  BallId get_id(const char* what) {
    BallId id;
    id.index = get<std::uint32_t>(what);
    id.generation = get<std::uint32_t>(what);
    return id;
  }
  [[nodiscard]] std::size_t left() const { return in_.size() - at_; }
  [[noreturn]] void fail(const std::string& problem) const {
    throw CheckpointError(file_ + ": " + problem);
  }

 private:
  void need(std::uint64_t size, const char* what) const {
    if (size > in_.size() - at_)
      fail(std::string("inconsistent content: ") + what + " runs past the end");
  }
  std::string_view in_;
  std::size_t at_ = 0;
  const std::string& file_;
};

void put_progress(Writer& w, const RunProgress& p) {
  w.put(p.mode);
  w.put(p.until);
  w.put(p.steps);
  w.put(p.dt);
  w.put(p.collisions);
  w.put(static_cast<std::uint8_t>(p.has_time_limit));
  w.put(p.time_limit);
  w.put(p.every);
  w.put(p.checkpoint_every);
  w.put(p.run_start_time);
  w.put(p.next_frame);
  w.put(p.next_chunk);
  w.put(p.next_checkpoint);
  w.put(p.steps_done);
  w.put(static_cast<std::uint8_t>(p.in_step));
  w.put(p.step_end);
  w.put(p.collisions_done);
  w.put(p.ball_ball);
  w.put(p.ball_wall);
  w.put(p.potted);
  w.put(p.last_frame_time);
  w.put(p.balls_at_start);
  w.put(p.energy_before);
  w.put(p.momentum_before_x);
  w.put(p.momentum_before_y);
  w.put(p.movable_mass);
  w.put_text(p.scene_file);
  w.put(p.potential_before);
}

bool get_flag(Reader& r, const char* what) {
  const auto flag = r.get<std::uint8_t>(what);
  if (flag > 1)
    r.fail(std::string("inconsistent content: ") + what + " is " + std::to_string(flag));
  return flag == 1;
}

RunProgress get_progress(Reader& r, std::uint32_t version) {
  RunProgress p;
  p.mode = r.get<std::uint8_t>("the run mode");
  if (p.mode > 3) r.fail("inconsistent content: unknown run mode " + std::to_string(p.mode));
  p.until = r.get<double>("--until");
  p.steps = r.get<std::uint64_t>("--steps");
  p.dt = r.get<double>("--dt");
  p.collisions = r.get<std::uint64_t>("--collisions");
  if (version >= 2) {
    p.has_time_limit = get_flag(r, "whether --time-limit was given");
    p.time_limit = r.get<double>("--time-limit");
  }
  p.every = r.get<double>("--every");
  p.checkpoint_every = r.get<double>("--checkpoint-every");
  p.run_start_time = r.get<double>("the run's start time");
  p.next_frame = r.get<std::uint64_t>("the next frame");
  p.next_chunk = r.get<std::uint64_t>("the next chunk");
  p.next_checkpoint = r.get<std::uint64_t>("the next checkpoint");
  p.steps_done = r.get<std::uint64_t>("the steps done");
  if (version >= 2) {
    p.in_step = get_flag(r, "whether a step is in progress");
    p.step_end = r.get<double>("the step's end");
  }
  p.collisions_done = r.get<std::uint64_t>("the collisions done");
  p.ball_ball = r.get<std::uint64_t>("the ball-ball count");
  p.ball_wall = r.get<std::uint64_t>("the ball-wall count");
  p.potted = r.get<std::uint64_t>("the potted count");
  p.last_frame_time = r.get<double>("the last frame time");
  p.balls_at_start = r.get<std::uint64_t>("the balls at start");
  p.energy_before = r.get<double>("the energy at start");
  p.momentum_before_x = r.get<double>("the momentum at start");
  p.momentum_before_y = r.get<double>("the momentum at start");
  p.movable_mass = r.get<double>("the movable mass");
  p.scene_file = std::string(r.get_text("the scene file name"));
  if (version >= 3) p.potential_before = r.get<double>("the potential energy at start");
  return p;
}

[[noreturn]] void damaged(const std::string& file, const std::string& problem) {
  throw CheckpointError(file + ": " + problem);
}

}  // namespace

std::string encode_checkpoint(const SceneWorld& built, const RunProgress& progress) {
  Writer content;
  put_progress(content, progress);
  content.put(built.start_time);
  content.put_text(to_json_text(built.scene));
  content.put<std::uint64_t>(built.balls.size());
  for (const BallId id : built.balls) content.put_id(id);
  content.put<std::uint64_t>(built.pockets.size());
  for (const WallId wall : built.pockets) content.put<std::uint32_t>(wall);
  // by_name in name order, so the same state always gives the same bytes.
  std::vector<std::pair<std::string, BallId>> names(built.by_name.begin(), built.by_name.end());
  std::sort(names.begin(), names.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  content.put<std::uint64_t>(names.size());
  for (const auto& [name, id] : names) {
    content.put_text(name);
    content.put_id(id);
  }
  std::ostringstream world(std::ios::binary);
  built.world.save(world);
  content.put_text(world.str());
  content.put<std::uint64_t>(built.shots_taken);

  Writer file;
  file.bytes() = kMagic;
  file.put(kVersion);
  file.put<std::uint64_t>(content.bytes().size());
  file.put(checksum(content.bytes()));
  file.bytes() += content.bytes();
  return std::move(file.bytes());
}

Checkpoint decode_checkpoint(std::string_view bytes, const std::string& file) {
  if (bytes.size() < kMagic.size() || bytes.substr(0, kMagic.size()) != kMagic) {
    damaged(file, "not a carom checkpoint (bad magic)");
  }
  if (bytes.size() < kHeaderSize) damaged(file, "truncated: the header is incomplete");
  Reader header(bytes.substr(kMagic.size(), kHeaderSize - kMagic.size()), file);
  const auto version = header.get<std::uint32_t>("the version");
  if (version < kOldestVersion || version > kVersion) {
    damaged(file, "unsupported version " + std::to_string(version) +
                      " (this build reads versions " + std::to_string(kOldestVersion) + " to " +
                      std::to_string(kVersion) + ")");
  }
  const auto size = header.get<std::uint64_t>("the content size");
  const auto expected = header.get<std::uint64_t>("the checksum");
  const std::string_view content = bytes.substr(kHeaderSize);
  if (content.size() < size) {
    damaged(file, "truncated: the header says " + std::to_string(size) +
                      " bytes of content, the file has " + std::to_string(content.size()));
  }
  if (content.size() > size) {
    damaged(file, std::to_string(content.size() - size) + " unexpected bytes after the end");
  }
  if (checksum(content) != expected) damaged(file, "checksum mismatch: the file is damaged");

  Reader r(content, file);
  RunProgress progress = get_progress(r, version);
  const auto start_time = r.get<double>("the start time");
  Scene scene;
  try {
    scene = parse_scene(r.get_text("the scene"), file + " (its scene)");
  } catch (const SceneError& error) {
    damaged(file, std::string("inconsistent content: the scene in it: ") + error.what());
  }
  const auto read_ids = [&](const char* what) {
    const auto count = r.get<std::uint64_t>(what);
    // Each id takes 8 bytes; a count larger than what is left is damage, not a reason to allocate.
    if (count > r.left() / 8) r.fail(std::string("inconsistent content: ") + what + " count");
    std::vector<BallId> ids(count);
    for (BallId& id : ids) id = r.get_id(what);
    return ids;
  };
  std::vector<BallId> balls = read_ids("the ball ids");
  if (balls.size() != scene.balls.size()) {
    damaged(file, "inconsistent content: " + std::to_string(balls.size()) + " ball ids for " +
                      std::to_string(scene.balls.size()) + " scene balls");
  }
  const auto pocket_count = r.get<std::uint64_t>("the pocket count");
  if (pocket_count != scene.pockets.size()) {
    damaged(file, "inconsistent content: " + std::to_string(pocket_count) + " pocket ids for " +
                      std::to_string(scene.pockets.size()) + " scene pockets");
  }
  std::vector<WallId> pockets(scene.pockets.size());
  for (WallId& wall : pockets) wall = r.get<std::uint32_t>("a pocket's wall id");
  std::unordered_map<std::string, BallId> by_name;
  const auto names = r.get<std::uint64_t>("the names");
  if (names > r.left()) r.fail("inconsistent content: the names count");
  for (std::uint64_t i = 0; i < names; ++i) {
    std::string name(r.get_text("a name"));
    by_name[std::move(name)] = r.get_id("a name's id");
  }
  const std::string world_bytes(r.get_text("the world"));
  const std::uint64_t shots_taken = version >= 5 ? r.get<std::uint64_t>("the shots struck") : 0;
  if (shots_taken > scene.shots.size()) {
    damaged(file, "inconsistent content: " + std::to_string(shots_taken) + " shots struck of " +
                      std::to_string(scene.shots.size()));
  }
  if (r.left() != 0) damaged(file, "inconsistent content: bytes after the world");
  std::istringstream world_in(world_bytes, std::ios::binary);
  std::optional<World> world;
  try {
    world.emplace(World::load(world_in));
  } catch (const std::exception& error) {
    damaged(file, std::string("the world in it: ") + error.what());
  }
  // The pockets must be the world's remove_ball sensors.
  for (const WallId wall : pockets) {
    if (wall >= world->wall_count() || world->sensor(wall) != SensorAction::remove_ball) {
      damaged(file, "inconsistent content: pocket wall " + std::to_string(wall) +
                        " is not a sensor that removes balls");
    }
  }
  // The scene's sensors are the world's last walls before the pockets (make_world adds them so).
  std::vector<WallId> sensors;
  if (world->wall_count() < scene.pockets.size() + scene.sensors.size()) {
    damaged(file, "inconsistent content: the world has fewer walls than the scene's sensors");
  }
  const std::size_t first_sensor =
      world->wall_count() - scene.pockets.size() - scene.sensors.size();
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    sensors.push_back(static_cast<WallId>(first_sensor + k));
  }
  return {SceneWorld{std::move(*world),
                     std::move(scene),
                     std::move(balls),
                     std::move(pockets),
                     std::move(by_name),
                     start_time,
                     0.0,
                     std::move(sensors),
                     {},
                     shots_taken,
                     {}},
          std::move(progress)};
}

std::optional<std::string> write_checkpoint(const std::string& name, std::string_view bytes) {
  try {
    // Through a link, the checkpoints rotate beside its target; the link stays.
    AtomicFile file(name, {.temporary = TemporaryName::fixed, .sync = true, .keep_previous = true});
    const TemporaryFileGuard guard(file.temporary().string());
    file.write(bytes);
    file.commit();
  } catch (const FileError& error) {
    return "cannot write " + name + ": " + error.reason();
  }
  return std::nullopt;
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::string problem = path + ": cannot be read: " + std::strerror(errno);
    std::error_code ignored;
    if (std::filesystem::exists(path + ".prev", ignored)) {
      problem += " (" + path + ".prev holds the checkpoint before it)";
    }
    throw CheckpointError(problem);
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw CheckpointError(path + ": cannot be read");
  return decode_checkpoint(bytes, path);
}

}  // namespace carom::cli
