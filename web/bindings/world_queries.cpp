#include "world_queries.hpp"

#include <span>
#include <string>
#include <vector>

#include "carom/sweep.hpp"
#include "carom/world.hpp"
#include "js_error.hpp"

namespace carom::web {
namespace {

using emscripten::val;

bool flag(const val& filter, const char* key) {
  const val value = filter[std::string(key)];
  return value.isUndefined() || value.isNull() || value.as<bool>();
}

// The page's filter as a QueryFilter. The accept function it builds holds `filter` (a copy of the
// JavaScript handle) and `w`, both alive for the query's call.
QueryFilter query_filter(const DrawnWorld& w, const val& filter) {
  QueryFilter out;
  if (filter.isUndefined() || filter.isNull()) return out;
  out.balls = flag(filter, "balls");
  out.walls = flag(filter, "walls");
  const val ignore = filter["ignore"];
  if (ignore.isNumber() && ignore.as<int>() >= 0) out.ignore = w.handle(ignore.as<int>());
  const val accept = filter["accept"];
  if (accept.typeOf().as<std::string>() == "function") {
    out.accept = [&w, accept](BallId ball) { return accept(w.index_of(ball)).as<bool>(); };
  }
  return out;
}

val point(Vec2 p) {
  val out = val::object();
  out.set("x", p.x);
  out.set("y", p.y);
  return out;
}

// A hit, or the pocket `pocket` (>= 0) the moving ball reaches first.
val hit_object(const DrawnWorld& w, const QueryHit& hit, int pocket = -1) {
  val out = val::object();
  int ball = -1;
  int wall = -1;
  std::string kind = "none";
  if (pocket >= 0) {
    kind = "pocket";
  } else if (hit.kind == HitKind::ball) {
    kind = "ball";
    ball = w.index_of(hit.ball);
  } else if (hit.kind == HitKind::wall) {
    kind = "wall";
    wall = static_cast<int>(hit.wall);
  }
  out.set("kind", kind);
  out.set("ball", ball);
  out.set("pocket", pocket);
  out.set("wall", wall);
  out.set("boundary", wall >= 0 && wall < 4 && w.def().boundary == Boundary::box);
  out.set("fraction", hit.fraction);
  out.set("point", point(hit.point));
  out.set("normal", point(hit.normal));
  out.set("center", point(hit.center));
  out.set("overlapping", hit.overlapping);
  return out;
}

}  // namespace

val cast_ball(const DrawnWorld& w, Vec2 center, double radius, Vec2 translation,
              const val& filter) {
  return guarded_call([&] {
    QueryHit hit = w.world().cast_ball(center, radius, translation, query_filter(w, filter));
    // Pockets are sensors, which the world's queries do not see: the page asks them itself
    // (unless its filter says "pockets: false"), as the moving ball's first touch of each disc.
    int pocket = -1;
    const bool pockets = filter.isUndefined() || filter.isNull() || flag(filter, "pockets");
    const std::vector<ScenePocket>& discs = w.pockets();
    for (std::size_t k = 0; pockets && k < discs.size(); ++k) {
      const Impact touch =
          sweep_ball_ball({center, radius}, translation, {discs[k].position, discs[k].radius});
      if (!touch.hit || touch.overlapping || (hit && hit.fraction <= touch.t)) continue;
      hit = QueryHit{};
      hit.kind = HitKind::ball;  // (a stand-in: hit_object names the pocket)
      hit.fraction = touch.t;
      hit.normal = -touch.normal;
      hit.point = touch.point;
      hit.center = touch.a_at;
      pocket = static_cast<int>(k);
    }
    return hit_object(w, hit, pocket);
  });
}

val balls_in_circle(const DrawnWorld& w, Vec2 center, double radius, const val& filter) {
  return guarded_call([&] {
    const QueryFilter query = query_filter(w, filter);
    val out = val::array();
    for (const BallId ball : w.world().balls_in_circle(center, radius, query)) {
      out.call<void>("push", w.index_of(ball));
    }
    return out;
  });
}

val step_contacts(const DrawnWorld& w) {
  val out = val::array();
  const std::span<const ContactEvent> contacts = w.step_contacts();
  const std::span<const SensorEvent> sensed = w.step_sensor_events();
  std::size_t next = 0;
  // A pocket's sensor taking a ball, in its place among the contacts: as a contact of kind
  // "pocket" at the pocket's centre.
  const auto pockets_before = [&](std::size_t before) {
    for (; next < sensed.size() && sensed[next].contacts_before <= before; ++next) {
      const SensorEvent& e = sensed[next];
      const int pocket = w.pocket_of(e.sensor);
      if (pocket < 0 || !e.removed) continue;
      val contact = val::object();
      contact.set("time", e.time);
      contact.set("kind", std::string("pocket"));
      contact.set("a", w.index_of(e.ball));
      contact.set("b", -1);
      contact.set("pocket", pocket);
      contact.set("wall", -1);
      contact.set("point", point(w.pockets()[static_cast<std::size_t>(pocket)].position));
      contact.set("normal", point({}));
      contact.set("approach_speed", 0.0);
      contact.set("impulse", 0.0);
      out.call<void>("push", contact);
    }
  };
  for (std::size_t n = 0; n < contacts.size(); ++n) {
    pockets_before(n);
    const ContactEvent& c = contacts[n];
    val contact = val::object();
    const int a = w.index_of(c.a);
    int b = -1;
    int wall = -1;
    const int pocket = -1;
    std::string kind;
    if (c.kind == ContactKind::ball_wall) {
      kind = "wall";
      wall = static_cast<int>(c.wall);
    } else {
      kind = "ball";
      b = w.index_of(c.b);
    }
    contact.set("time", c.time);
    contact.set("kind", kind);
    contact.set("a", a);
    contact.set("b", b);
    contact.set("pocket", pocket);
    contact.set("wall", wall);
    contact.set("point", point(c.point));
    contact.set("normal", point(c.normal));
    contact.set("approach_speed", c.approach_speed);
    contact.set("impulse", c.impulse);
    out.call<void>("push", contact);
  }
  pockets_before(contacts.size());
  return out;
}

}  // namespace carom::web
