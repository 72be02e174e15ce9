#include "drawing/trail_recorder.hpp"

#include <algorithm>
#include <cmath>

namespace carom::cli {

TrailRecorder::TrailRecorder(const SceneWorld& scene_world, double seconds)
    : seconds_(seconds), points_(scene_world.scene.balls.size()) {
  const WorldDef& settings = scene_world.scene.world;
  if (settings.boundary == Boundary::periodic) period_ = settings.upper - settings.lower;
}

void TrailRecorder::add(std::size_t ball, double time, Vec2 at) {
  std::deque<Point>& points = points_[ball];
  if (!points.empty() && points.back().time == time && points.back().at == at) return;
  points.push_back({time, at});
  // Forget what lies wholly before the window: keep one point before it, to cut the path at the
  // window's start.
  while (points.size() > 2 && points[1].time <= time - seconds_) points.pop_front();
}

namespace {

// Calls visit(scene index, centre) for each ball of the contact: the contact point lies on each
// ball's surface along the normal (from a towards b), so each centre is one radius back from it.
template <typename Visit>
void visit_centres(const SceneWorld& scene_world, const ContactEvent& contact, Visit visit) {
  if (const std::optional<std::size_t> a = scene_world.index_of(contact.a)) {
    visit(*a, contact.point - contact.normal * scene_world.scene.balls[*a].radius);
  }
  if (contact.kind == ContactKind::ball_ball) {
    if (const std::optional<std::size_t> b = scene_world.index_of(contact.b)) {
      visit(*b, contact.point + contact.normal * scene_world.scene.balls[*b].radius);
    }
  }
}

}  // namespace

ViewBox contact_centres(const SceneWorld& scene_world, std::span<const ContactEvent> contacts) {
  ViewBox box;
  for (const ContactEvent& contact : contacts) {
    visit_centres(scene_world, contact, [&](std::size_t, Vec2 centre) { box.add(centre); });
  }
  return box;
}

void TrailRecorder::record(const SceneWorld& scene_world, std::span<const ContactEvent> contacts) {
  for (const ContactEvent& contact : contacts) {
    visit_centres(scene_world, contact,
                  [&](std::size_t ball, Vec2 centre) { add(ball, contact.time, centre); });
  }
  const double now = scene_world.world.time();
  for (std::size_t i = 0; i < scene_world.balls.size(); ++i) {
    const BallId id = scene_world.balls[i];
    if (!id.is_null() && scene_world.world.contains(id))
      add(i, now, scene_world.world.position(id));
  }
}

Vec2 TrailRecorder::shortest(Vec2 from, Vec2 to) const {
  Vec2 d = to - from;
  if (period_) {
    d.x -= period_->x * std::round(d.x / period_->x);
    d.y -= period_->y * std::round(d.y / period_->y);
  }
  return d;
}

std::vector<std::vector<Vec2>> TrailRecorder::paths(std::size_t ball, double now) const {
  std::vector<std::vector<Vec2>> runs;
  const std::deque<Point>& points = points_[ball];
  const double start = now - seconds_;
  std::vector<Vec2> run;
  for (std::size_t i = 0; i < points.size() && points[i].time <= now; ++i) {
    const Point& p = points[i];
    if (p.time < start) continue;
    if (run.empty() && i > 0) {
      // The window starts between the previous point and this one: cut the path there.
      const Point& q = points[i - 1];
      const double w = (start - q.time) / (p.time - q.time);
      run.push_back(p.at - shortest(q.at, p.at) * (1.0 - w));
    }
    if (!run.empty()) {
      const Vec2 step = shortest(run.back(), p.at);
      if (step != p.at - run.back()) {
        // Wrapped around the cell: finish this run outside the cell, start the next outside too.
        run.push_back(run.back() + step);
        runs.push_back(std::move(run));
        run = {p.at - step};
      }
    }
    run.push_back(p.at);
  }
  if (run.size() >= 2) runs.push_back(std::move(run));
  // A ball that stood still has no trail to draw.
  std::erase_if(runs, [](const std::vector<Vec2>& r) {
    return std::all_of(r.begin(), r.end(), [&](Vec2 p) { return p == r.front(); });
  });
  return runs;
}

ViewBox TrailRecorder::extent(double now) const {
  ViewBox box;
  for (std::size_t ball = 0; ball < points_.size(); ++ball) {
    for (const std::vector<Vec2>& run : paths(ball, now)) {
      for (const Vec2 p : run) box.add(p);
    }
  }
  return box;
}

}  // namespace carom::cli
