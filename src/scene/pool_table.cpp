// Standard pool tables as scenes: the WPA's playing surfaces, pocket mouths and jaw angles, a
// rack on the foot spot. The geometry and why each piece is where it is: docs/pool.md, "Standard
// tables".
#include "carom/pool_table.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/number_text.hpp"

namespace carom {
namespace {

constexpr double kInch = 0.0254;
// The mouths between the jaws' tips (WPA: 4.5 to 4.625 inches at a corner, 5 to 5.125 at a
// side), and the jaws' angles to the cushion line (142° and 104°): a jaw turns 38° and 76° off
// it, into the pocket.
constexpr double kCornerMouth = 4.6 * kInch;
constexpr double kSideMouth = 5.1 * kInch;
constexpr double kCornerJawTurn = 38.0 * std::numbers::pi / 180.0;
constexpr double kSideJawTurn = 76.0 * std::numbers::pi / 180.0;
// How far the jaws reach behind the cushion line, and how far behind the mouth the pocket's disc
// sits: a ball is taken once it is past the jaws' tips, and one that meets a jaw bounces off it.
constexpr double kCornerJawLength = 0.06;
constexpr double kSideJawLength = 0.04;
constexpr double kCornerPocketDepth = 0.03;
constexpr double kSidePocketDepth = 0.05;
// The disc stops this short of the jaws' ends (a micrometre), so that no rounding lays it over
// them.
constexpr double kClearance = 1e-6;
// The box around the rails, beyond the pockets.
constexpr double kRailRoom = 0.2;

const std::array<const char*, 16> kColours = {
    "#f8f8f0",                                                                     // the cue ball
    "#f2c500", "#1a3fa0", "#c01818", "#5a2a82", "#e86a10", "#137030", "#7a1a1a",   // 1 to 7
    "#111111",                                                                     // 8
    "#f2c500", "#1a3fa0", "#c01818", "#5a2a82", "#e86a10", "#137030", "#7a1a1a"};  // 9 to 15

Vec2 surface(PoolTableSize size) {
  switch (size) {
    case PoolTableSize::seven_foot:
      return Vec2{78.0, 39.0} * kInch;
    case PoolTableSize::eight_foot:
      return Vec2{88.0, 44.0} * kInch;
    case PoolTableSize::nine_foot:
      break;
  }
  return Vec2{100.0, 50.0} * kInch;
}

struct Builder {
  Scene scene;

  void segment(Vec2 a, Vec2 b) { scene.segments.push_back({a, b}); }

  // A corner pocket at `corner`, its rails running from it along `along_a` and `along_b` (unit
  // vectors into the table): each cushion ends where the mouth opens, a jaw runs on from there
  // into the pocket, and the disc sits on the diagonal behind the mouth, reaching the jaws' ends.
  void corner_pocket(Vec2 corner, Vec2 along_a, Vec2 along_b, const std::string& name) {
    const double end = kCornerMouth / std::numbers::sqrt2;
    const Vec2 tip_a = corner + along_a * end;
    const Vec2 tip_b = corner + along_b * end;
    const double c = std::cos(kCornerJawTurn);
    const double s = std::sin(kCornerJawTurn);
    const Vec2 jaw_a = tip_a + (along_a * -c - along_b * s) * kCornerJawLength;
    const Vec2 jaw_b = tip_b + (along_b * -c - along_a * s) * kCornerJawLength;
    segment(tip_a, jaw_a);
    segment(tip_b, jaw_b);
    const Vec2 centre = corner - (along_a + along_b) * kCornerPocketDepth;
    scene.pockets.push_back({name, centre, length(jaw_a - centre) - kClearance});
  }

  // A side pocket in the middle of a rail at `middle`, the rail along `along`, `out` away from the
  // table.
  void side_pocket(Vec2 middle, Vec2 along, Vec2 out, const std::string& name) {
    const Vec2 tip_a = middle - along * (0.5 * kSideMouth);
    const Vec2 tip_b = middle + along * (0.5 * kSideMouth);
    const double c = std::cos(kSideJawTurn);
    const double s = std::sin(kSideJawTurn);
    const Vec2 jaw_a = tip_a + (along * c + out * s) * kSideJawLength;
    const Vec2 jaw_b = tip_b + (along * -c + out * s) * kSideJawLength;
    segment(tip_a, jaw_a);
    segment(tip_b, jaw_b);
    const Vec2 centre = middle + out * kSidePocketDepth;
    scene.pockets.push_back({name, centre, length(jaw_a - centre) - kClearance});
  }

  void ball(const std::string& name, Vec2 at, const PoolTableSpec& spec, std::size_t colour) {
    SceneBall b;
    b.name = name;
    b.position = at;
    b.radius = spec.ball_radius;
    b.mass = spec.ball_mass;
    b.color = kColours[colour];
    scene.balls.push_back(b);
  }
};

void require(bool ok, const char* argument, double value, const char* requirement) {
  if (!ok) throw InvalidArgument("pool_table_scene", argument, number_text(value), requirement);
}

}  // namespace

Scene pool_table_scene(const PoolTableSpec& spec) {
  require(std::isfinite(spec.ball_radius) && spec.ball_radius > 0.0, "spec.ball_radius",
          spec.ball_radius, "must be finite and > 0");
  require(std::isfinite(spec.ball_mass) && spec.ball_mass > 0.0, "spec.ball_mass", spec.ball_mass,
          "must be finite and > 0");
  require(std::isfinite(spec.rack_gap) && spec.rack_gap >= 0.0, "spec.rack_gap", spec.rack_gap,
          "must be finite and >= 0");
  const Vec2 size = surface(spec.size);
  const double length_x = size.x;
  const double width_y = size.y;
  require(spec.ball_radius * 12.0 < width_y, "spec.ball_radius", spec.ball_radius,
          "must leave the table room for a rack");

  Builder b;
  Scene& scene = b.scene;
  const char* names[] = {"7-foot", "8-foot", "9-foot"};
  scene.description = std::string("A ") + names[static_cast<int>(spec.size)] +
                      " pool table (carom::pool_table_scene): cushions with jaws at six pockets, "
                      "the rack on the foot spot, the cue ball on the head spot.";
  scene.world.boundary = Boundary::box;
  scene.world.lower = {-kRailRoom, -kRailRoom};
  scene.world.upper = {length_x + kRailRoom, width_y + kRailRoom};
  scene.world.restitution = 0.95;
  scene.world.table = Table{};

  // The cushions' noses, from mouth to mouth.
  const double corner_end = kCornerMouth / std::numbers::sqrt2;
  const double half_side = 0.5 * kSideMouth;
  for (const double y : {0.0, width_y}) {
    b.segment({corner_end, y}, {0.5 * length_x - half_side, y});
    b.segment({0.5 * length_x + half_side, y}, {length_x - corner_end, y});
  }
  for (const double x : {0.0, length_x}) b.segment({x, corner_end}, {x, width_y - corner_end});
  // The pockets and their jaws.
  b.corner_pocket({0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, "bottom-left");
  b.side_pocket({0.5 * length_x, 0.0}, {1.0, 0.0}, {0.0, -1.0}, "bottom-middle");
  b.corner_pocket({length_x, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, "bottom-right");
  b.corner_pocket({0.0, width_y}, {1.0, 0.0}, {0.0, -1.0}, "top-left");
  b.side_pocket({0.5 * length_x, width_y}, {1.0, 0.0}, {0.0, 1.0}, "top-middle");
  b.corner_pocket({length_x, width_y}, {-1.0, 0.0}, {0.0, -1.0}, "top-right");

  b.ball("cue", {0.25 * length_x, 0.5 * width_y}, spec, 0);
  // Rows from the apex on the foot spot towards the foot rail.
  std::vector<std::vector<int>> rows;
  if (spec.rack == PoolRack::eight_ball) {
    rows = {{1}, {9, 2}, {10, 8, 3}, {11, 4, 12, 5}, {13, 6, 14, 7, 15}};
  } else if (spec.rack == PoolRack::nine_ball) {
    rows = {{1}, {2, 3}, {4, 9, 5}, {6, 7}, {8}};
  }
  const double spacing = 2.0 * spec.ball_radius + spec.rack_gap;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double x = 0.75 * length_x + static_cast<double>(k) * spacing * std::sqrt(3.0) / 2.0;
    const double count = static_cast<double>(rows[k].size());
    for (std::size_t j = 0; j < rows[k].size(); ++j) {
      const double y = 0.5 * width_y + (static_cast<double>(j) - 0.5 * (count - 1.0)) * spacing;
      const int number = rows[k][j];
      b.ball(std::to_string(number), {x, y}, spec, static_cast<std::size_t>(number));
    }
  }
  return scene;
}

}  // namespace carom
