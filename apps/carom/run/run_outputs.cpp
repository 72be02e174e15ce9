#include "run/run_outputs.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <limits>
#include <nlohmann/json.hpp>

namespace carom::cli {
namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
  std::string extension = path.substr(dot);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// The XYZ species of a ball: its name up to a '#' (a generator's balls share their generator's
// name), or "ball". Spaces would split the column, so they become underscores.
std::string species(const SceneBall& ball) {
  if (!ball.name || ball.name->empty()) return "ball";
  std::string name = ball.name->substr(0, ball.name->find('#'));
  if (name.empty()) return "ball";
  for (char& c : name) {
    if (std::isspace(static_cast<unsigned char>(c)) != 0 || c == '"') c = '_';
  }
  return name;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

std::optional<FrameFormat> frame_format_of(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".csv") return FrameFormat::csv;
  if (extension == ".xyz") return FrameFormat::xyz;
  return std::nullopt;
}

BallDirectory::BallDirectory(const SceneWorld& built) {
  for (std::size_t i = 0; i < built.balls.size(); ++i) {
    if (!built.balls[i].is_null()) balls_.emplace(key(built.balls[i]), i);
  }
}

std::uint64_t BallDirectory::key(BallId id) {
  return (static_cast<std::uint64_t>(id.generation) << 32U) | id.index;
}

std::optional<std::size_t> BallDirectory::ball_index(BallId id) const {
  const auto found = balls_.find(key(id));
  if (found == balls_.end()) return std::nullopt;
  return found->second;
}

void FrameWriter::write_frame(const SceneWorld& built) {
  const double time = built.time();
  std::size_t live = 0;
  for (const BallId id : built.balls) live += id.is_null() ? 0U : 1U;
  buffer_.clear();
  if (format_ == FrameFormat::csv) {
    if (frames_ == 0) buffer_ += "time,index,name,x,y,vx,vy,radius\n";
  } else {
    // Extended XYZ as OVITO and ASE read it: 3D columns with z = 0, the box or cell as Lattice
    // with its Origin, periodicity per axis.
    buffer_ += std::to_string(live) + "\n";
    const WorldDef& w = scene_->world;
    if (w.boundary != Boundary::open) {
      const Vec2 size = w.upper - w.lower;
      buffer_ += "Lattice=\"" + number_text(size.x) + " 0 0 0 " + number_text(size.y) +
                 " 0 0 0 1\" Origin=\"" + number_text(w.lower.x) + " " + number_text(w.lower.y) +
                 " -0.5\" ";
      buffer_ += w.boundary == Boundary::periodic ? "pbc=\"T T F\" " : "pbc=\"F F F\" ";
    }
    buffer_ +=
        "Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:index:I:1 Time=" + number_text(time) +
        "\n";
  }
  for (std::size_t i = 0; i < built.balls.size(); ++i) {
    const BallId id = built.balls[i];
    if (id.is_null()) continue;
    const Vec2 p = built.world.position(id);
    const Vec2 v = built.world.velocity(id);
    const SceneBall& ball = built.scene.balls[i];
    if (format_ == FrameFormat::csv) {
      buffer_ += number_text(time) + "," + std::to_string(i) + "," +
                 csv_field(ball.name.value_or("")) + "," + number_text(p.x) + "," +
                 number_text(p.y) + "," + number_text(v.x) + "," + number_text(v.y) + "," +
                 number_text(ball.radius) + "\n";
    } else {
      buffer_ += species(ball) + " " + number_text(p.x) + " " + number_text(p.y) + " 0 " +
                 number_text(v.x) + " " + number_text(v.y) + " 0 " + number_text(ball.radius) +
                 " " + std::to_string(i) + "\n";
    }
  }
  out_.write(buffer_);
  ++frames_;
}

void EventWriter::write(const std::vector<ContactEvent>& contacts, const BallDirectory& directory,
                        const SceneWorld& built, std::size_t wall_offset) {
  buffer_.clear();
  const auto index_json = [&](BallId id) -> nlohmann::ordered_json {
    if (const auto i = directory.ball_index(id)) return *i;
    return nullptr;
  };
  // On a table, the balls' changes of motion state, in time order among the contacts and the
  // sensors' events (a change a contact makes comes after it).
  std::size_t next_motion_event = 0;
  const auto write_motion_events = [&](double before) {
    for (; next_motion_event < built.motion_events.size() &&
           built.motion_events[next_motion_event].time < before;
         ++next_motion_event) {
      const MotionEvent& e = built.motion_events[next_motion_event];
      nlohmann::ordered_json line;
      line["time"] = built.start_time + e.time;
      line["kind"] = "motion";
      line["ball"] = index_json(e.ball);
      line["from"] = motion_state_name(e.from);
      line["to"] = motion_state_name(e.to);
      buffer_ += line.dump() + "\n";
    }
  };
  std::size_t next_sensor_event = 0;
  // The sensor events placed before contact `before` (all that are left for contacts.size()).
  const auto write_sensor_events = [&](std::size_t before) {
    for (; next_sensor_event < built.sensor_events.size() &&
           built.sensor_events[next_sensor_event].contacts_before <= before;
         ++next_sensor_event) {
      const SensorEvent& e = built.sensor_events[next_sensor_event];
      write_motion_events(e.time);
      nlohmann::ordered_json line;
      line["time"] = built.start_time + e.time;
      const auto pocket = std::find(built.pockets.begin(), built.pockets.end(), e.sensor);
      if (pocket != built.pockets.end()) {
        // A pocket's sensor took the ball: numbered among the scene's pockets.
        line["kind"] = "potted";
        line["ball"] = index_json(e.ball);
        line["pocket"] = pocket - built.pockets.begin();
        buffer_ += line.dump() + "\n";
        continue;
      }
      line["kind"] = e.kind == SensorEventKind::enter ? "sensor_enter" : "sensor_exit";
      line["ball"] = index_json(e.ball);
      // Numbered among the scene's sensors.
      const auto sensor = std::find(built.sensors.begin(), built.sensors.end(), e.sensor);
      line["sensor"] = sensor - built.sensors.begin();
      if (e.removed) line["removed"] = true;
      buffer_ += line.dump() + "\n";
    }
  };
  for (std::size_t n = 0; n < contacts.size(); ++n) {
    write_sensor_events(n);
    const ContactEvent& c = contacts[n];
    write_motion_events(c.time);
    nlohmann::ordered_json line;
    line["time"] = built.start_time + c.time;
    if (c.kind == ContactKind::ball_ball) {
      line["kind"] = "ball_ball";
      line["a"] = index_json(c.a);
      line["b"] = index_json(c.b);
    } else {
      line["kind"] = "ball_wall";
      line["a"] = index_json(c.a);
      // Box walls are the world's 0-3; the scene's own walls are numbered from 0 after them.
      if (c.wall < wall_offset) {
        line["box_wall"] = c.wall;
      } else {
        line["wall"] = c.wall - wall_offset;
      }
    }
    line["point"] = {c.point.x, c.point.y};
    line["normal"] = {c.normal.x, c.normal.y};
    line["approach_speed"] = c.approach_speed;
    line["impulse"] = c.impulse;
    buffer_ += line.dump() + "\n";
  }
  write_sensor_events(contacts.size());
  write_motion_events(std::numeric_limits<double>::infinity());
  out_.write(buffer_);
}

}  // namespace carom::cli
