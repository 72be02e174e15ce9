#include "sweep/sweep_svg.hpp"

#include <fmt/format.h>

#include "drawing/svg_writer.hpp"
#include "options/readable_number.hpp"

namespace carom::cli {
namespace {

// A is red and B is blue throughout, as in the tutorial; the relative movement v3 is green.
// Fills are pale so the arrows on top stay clear; the velocities after are darker shades.
constexpr const char* kRed = "#d62728";
constexpr const char* kPaleRed = "#f2b0b0";
constexpr const char* kDarkRed = "#8b1a1a";
constexpr const char* kBlue = "#1f6fb4";
constexpr const char* kPaleBlue = "#b0d0ec";
constexpr const char* kDarkBlue = "#0b3d6b";
constexpr const char* kGreen = "#2a9d2a";
constexpr const char* kGrey = "#808080";
constexpr const char* kBlack = "#222222";

// Line widths, in the figure's line widths: outlines and helper lines thin, the movements medium,
// the results (velocities after the bounce) thick.
constexpr double kThin = 1.0;
constexpr double kMedium = 1.5;
constexpr double kThick = 2.5;

const Pen kMoveA{kRed, kMedium};
const Pen kMoveB{kBlue, kMedium};
const Pen kRelativeMove{kGreen, kMedium, true};
const Pen kContactA{kRed, kMedium};
const Pen kContactB{kBlue, kMedium};
const Pen kPartA{kRed, kThin, true};
const Pen kPartB{kBlue, kThin, true};
const Pen kAfterA{kDarkRed, kThick};
const Pen kAfterB{kDarkBlue, kThick};

std::string mass(double value) { return value == kImmovable ? "immovable" : readable(value); }

// An arrow from `from` by `by`, labelled beyond its tip, or beside it or beside the middle of
// the arrow where that hides fewer lines.
void labelled_arrow(SvgFigure& figure, Vec2 from, Vec2 by, const Pen& pen, const char* name) {
  if (by == Vec2{}) return;
  const Vec2 tip = from + by;
  const Vec2 middle = from + by / 2.0;
  figure.arrow(from, tip, pen);
  figure.label({{tip, by},
                {tip, left_normal(by)},
                {tip, right_normal(by)},
                {middle, left_normal(by)},
                {middle, right_normal(by)}},
               name, pen.colour);
}

// A ball's name inside it, on the side away from its movement arrow, or across from it.
void label_ball(SvgFigure& figure, Vec2 center, Vec2 move, const char* name, const char* colour) {
  figure.label({{center, -move}, {center, left_normal(move)}, {center, right_normal(move)}}, name,
               colour);
}

// The balls where they start, named inside on the side away from their movement arrows, and
// the movements: va, vb and the relative one v3 = va − vb, all from the start centres.
void draw_start(SvgFigure& figure, const SweepCase& c, const SweepOutcome& outcome) {
  figure.circle(c.a.center, c.a.radius, {kRed, kThin}, kPaleRed);
  figure.circle(c.b.center, c.b.radius, {kBlue, kThin}, kPaleBlue);
  label_ball(figure, c.a.center, c.move_a, "A", kRed);
  label_ball(figure, c.b.center, c.move_b, "B", kBlue);
  labelled_arrow(figure, c.a.center, c.move_a, kMoveA, "va");
  labelled_arrow(figure, c.b.center, c.move_b, kMoveB, "vb");
  labelled_arrow(figure, c.a.center, outcome.relative_move, kRelativeMove, "v3");
}

void draw_contact_balls(SvgFigure& figure, const SweepCase& c, const Impact& impact) {
  figure.circle(impact.a_at, c.a.radius, kContactA);
  figure.circle(impact.b_at, c.b.radius, kContactB);
  figure.dot(impact.point, kBlack);
}

// The tutorial's construction at the contact: each movement split along the line of centres vc
// (v1a, v2a) and across it (v1b, v2b), and the velocities after the bounce. For equal masses
// and restitution 1 the balls swap the parts along vc: va′ = v1b + v2a, vb′ = v2b + v1a.
void draw_bounce(SvgFigure& figure, const SweepCase& c, const SweepOutcome& outcome) {
  const Impact& impact = outcome.impact;
  draw_contact_balls(figure, c, impact);
  // vc runs through both centres and on to the balls' far sides, so it shows beside the arrows
  // that lie along it; its name goes at one of its ends.
  const Vec2 n = impact.normal;
  const Vec2 vc_start = impact.a_at - n * c.a.radius;
  const Vec2 vc_end = impact.b_at + n * c.b.radius;
  figure.line(vc_start, vc_end, {kGrey, kThin});
  labelled_arrow(figure, impact.a_at, c.move_a, kMoveA, "va");
  labelled_arrow(figure, impact.b_at, c.move_b, kMoveB, "vb");
  const Components a = decompose(c.move_a, impact.normal);
  const Components b = decompose(c.move_b, impact.normal);
  labelled_arrow(figure, impact.a_at, a.along, kPartA, "v1a");
  labelled_arrow(figure, impact.a_at, a.across, kPartA, "v1b");
  labelled_arrow(figure, impact.b_at, b.along, kPartB, "v2a");
  labelled_arrow(figure, impact.b_at, b.across, kPartB, "v2b");
  if (outcome.bounce) {
    labelled_arrow(figure, impact.a_at, outcome.bounce->velocity_a, kAfterA, "va′");
    labelled_arrow(figure, impact.b_at, outcome.bounce->velocity_b, kAfterB, "vb′");
  }
  // Named last, at one of its ends or beside it inside a ball: the arrows' labels matter more
  // and take their places first.
  const Vec2 in_a = (impact.a_at + impact.point) / 2.0;
  const Vec2 in_b = (impact.b_at + impact.point) / 2.0;
  figure.label({{vc_start, -n},
                {vc_end, n},
                {vc_start, left_normal(n)},
                {vc_start, right_normal(n)},
                {vc_end, left_normal(n)},
                {vc_end, right_normal(n)},
                {in_a, left_normal(n)},
                {in_a, right_normal(n)},
                {in_b, left_normal(n)},
                {in_b, right_normal(n)}},
               "vc", kGrey);
}

void legend_start(SvgFigure& figure) {
  figure.legend(LegendMark::kDisc, {kRed, kThin}, "A at the start", kPaleRed);
  figure.legend(LegendMark::kDisc, {kBlue, kThin}, "B at the start", kPaleBlue);
  figure.legend(LegendMark::kArrow, kMoveA, "va: A's movement during the step");
  figure.legend(LegendMark::kArrow, kMoveB, "vb: B's movement during the step");
  figure.legend(LegendMark::kArrow, kRelativeMove, "v3 = va − vb: A's movement seen from B");
}

void legend_bounce(SvgFigure& figure) {
  figure.legend(LegendMark::kRing, kContactA, "A at the contact");
  figure.legend(LegendMark::kRing, kContactB, "B at the contact");
  figure.legend(LegendMark::kDot, {kBlack}, "the contact point");
  figure.legend(LegendMark::kLine, {kGrey, kThin}, "vc: the line of centres");
  figure.legend(LegendMark::kArrow, kPartA, "v1a, v1b: va along vc and across it");
  figure.legend(LegendMark::kArrow, kPartB, "v2a, v2b: vb along vc and across it");
  figure.legend(LegendMark::kArrow, kAfterA, "va′: A's velocity after the bounce");
  figure.legend(LegendMark::kArrow, kAfterB, "vb′: B's velocity after the bounce");
}

const Pen kEndA{kRed, kThin, true};
const Pen kEndB{kBlue, kThin, true};
const Pen kReach{kGreen, kThin, true};

// Without a contact: where the balls end the step, and why they miss. Seen from B, A's centre
// moves by v3 and touches B only by entering the circle of radius rA + rB around B's centre.
void draw_miss(SvgFigure& figure, const SweepCase& c) {
  figure.circle(c.a.center + c.move_a, c.a.radius, kEndA);
  figure.circle(c.b.center + c.move_b, c.b.radius, kEndB);
  figure.circle(c.b.center, c.a.radius + c.b.radius, kReach);
}

void legend_miss(SvgFigure& figure) {
  figure.legend(LegendMark::kRing, kEndA, "A at the end of the step");
  figure.legend(LegendMark::kRing, kEndB, "B at the end of the step");
  figure.legend(LegendMark::kRing, kReach, "rA + rB around B: v3 must enter it to touch");
}

}  // namespace

std::string sweep_svg(const SweepCase& c, const SweepOutcome& outcome) {
  SvgFigure figure;
  const Impact& impact = outcome.impact;
  if (!impact.hit) {
    figure.heading("No contact during the step");
    if (!impact.overlapping) {
      figure.heading("A and B pass each other without touching");
    } else if (outcome.relative_move == Vec2{}) {
      figure.heading("A and B overlap at the start and keep still relative to each other");
    } else {
      figure.heading("A and B overlap at the start and move apart");
    }
    draw_start(figure, c, outcome);
    draw_miss(figure, c);
    legend_start(figure);
    legend_miss(figure);
    return figure.render();
  }

  figure.heading(fmt::format("A and B touch at t = {} of the step", readable(impact.t)));
  figure.heading(fmt::format("masses {} and {}, restitution {}", mass(c.mass_a), mass(c.mass_b),
                             readable(c.restitution)));
  figure.panel("The step: where A and B start, how far they move, where they touch");
  draw_start(figure, c, outcome);
  draw_contact_balls(figure, c, impact);
  figure.panel("The bounce: the movements split along vc and across it, and after the bounce");
  draw_bounce(figure, c, outcome);
  legend_start(figure);
  legend_bounce(figure);
  return figure.render();
}

}  // namespace carom::cli
