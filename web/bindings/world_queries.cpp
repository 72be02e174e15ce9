#include "world_queries.hpp"

#include <functional>
#include <string>
#include <utility>

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
  const bool pockets = flag(filter, "pockets");
  const val ignore = filter["ignore"];
  if (ignore.isNumber() && ignore.as<int>() >= 0) out.ignore = w.handle(ignore.as<int>());
  const val accept = filter["accept"];
  const bool has_accept = accept.typeOf().as<std::string>() == "function";
  if (!pockets || has_accept) {
    out.accept = [&w, accept, pockets, has_accept](BallId ball) {
      if (w.pocket_of(ball) >= 0) return pockets;
      return !has_accept || accept(w.index_of(ball)).as<bool>();
    };
  }
  return out;
}

val point(Vec2 p) {
  val out = val::object();
  out.set("x", p.x);
  out.set("y", p.y);
  return out;
}

val hit_object(const DrawnWorld& w, const QueryHit& hit) {
  val out = val::object();
  int ball = -1;
  int pocket = -1;
  int wall = -1;
  std::string kind = "none";
  if (hit.kind == HitKind::ball) {
    pocket = w.pocket_of(hit.ball);
    if (pocket >= 0) {
      kind = "pocket";
    } else {
      kind = "ball";
      ball = w.index_of(hit.ball);
    }
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
    const QueryHit hit = w.world().cast_ball(center, radius, translation, query_filter(w, filter));
    return hit_object(w, hit);
  });
}

val balls_in_circle(const DrawnWorld& w, Vec2 center, double radius, const val& filter) {
  return guarded_call([&] {
    QueryFilter query = query_filter(w, filter);
    // Pockets are the World's balls but not the page's: never listed here.
    std::function<bool(BallId)> accept = std::move(query.accept);
    query.accept = [&w, &accept](BallId ball) {
      return w.pocket_of(ball) < 0 && (!accept || accept(ball));
    };
    val out = val::array();
    for (const BallId ball : w.world().balls_in_circle(center, radius, query)) {
      out.call<void>("push", w.index_of(ball));
    }
    return out;
  });
}

val step_contacts(const DrawnWorld& w) {
  val out = val::array();
  for (const ContactEvent& c : w.step_contacts()) {
    val contact = val::object();
    int a = w.index_of(c.a);
    int b = -1;
    int pocket = -1;
    int wall = -1;
    std::string kind;
    if (c.kind == ContactKind::ball_wall) {
      kind = "wall";
      wall = static_cast<int>(c.wall);
    } else if (const int pa = w.pocket_of(c.a); pa >= 0) {
      kind = "pocket";
      pocket = pa;
      a = w.index_of(c.b);
    } else if (const int pb = w.pocket_of(c.b); pb >= 0) {
      kind = "pocket";
      pocket = pb;
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
  return out;
}

}  // namespace carom::web
