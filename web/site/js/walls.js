// "Walls and arcs": one ball against two segments and an arc. carom::web::WallsScene finds the
// first contact (carom::sweep_ball_segment / sweep_ball_arc) and the bounce
// (carom::bounce_off_static); this page keeps the inputs and draws.
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {fillReadout, slider} from './sliders.js';
import {Figure, fillLegend} from './svg_figure.js';

const state = {
  ball: {center: {x: 0, y: 0}, radius: 0.8},
  move: {x: 9, y: 1},
  segments: [{a: {x: 6, y: -3}, b: {x: 6, y: 3}}, {a: {x: -1, y: 5}, b: {x: 5, y: 6.5}}],
  arcs: [{center: {x: 10, y: 1}, radius: 3, start_angle: -Math.PI / 2, end_angle: Math.PI / 2}],
};

const scene = new carom.WallsScene();
const figure = new Figure(document.getElementById('figure'), {x: -4, y: -4, width: 18, height: 13});
const radius = slider('radius', (r) => { state.ball.radius = r; redraw(); });
const restitution = slider('restitution', redraw);
state.ball.radius = radius.value;

const plus = (p, v) => ({x: p.x + v.x, y: p.y + v.y});
const minus = (p, q) => ({x: p.x - q.x, y: p.y - q.y});
const HANDLE_RADIUS = 0.45;  // world units: big enough to catch with a finger
const TAU = 2 * Math.PI;

// The arc's ends as handles: dragging one moves that end to the pointer's angle and sets the
// radius to the pointer's distance, keeping the other end where it is.
function arcEnd(arc, which) {
  return {
    get: () => {
      const angle = which === 'start' ? arc.start_angle : arc.end_angle;
      return {x: arc.center.x + arc.radius * Math.cos(angle),
              y: arc.center.y + arc.radius * Math.sin(angle)};
    },
    set: (p) => {
      const d = minus(p, arc.center);
      const r = Math.hypot(d.x, d.y);
      if (r === 0) return;
      const angle = Math.atan2(d.y, d.x);
      const span = (from, to) => ((to - from) % TAU + TAU) % TAU;
      arc.radius = r;
      if (which === 'start') {
        const end = arc.end_angle;
        arc.start_angle = angle;
        arc.end_angle = angle + span(angle, end);
      } else {
        arc.end_angle = arc.start_angle + span(arc.start_angle, angle);
      }
    },
    radius: () => HANDLE_RADIUS,
  };
}

figure.handle('ball', {get: () => state.ball.center, set: (p) => { state.ball.center = p; },
                       radius: () => state.ball.radius, cls: 'ball-handle', ball: true}, redraw);
figure.handle('move-end', {get: () => plus(state.ball.center, state.move),
                           set: (p) => { state.move = minus(p, state.ball.center); },
                           radius: () => HANDLE_RADIUS}, redraw);
state.segments.forEach((segment, i) => {
  for (const end of ['a', 'b']) {
    figure.handle(`segment${i}-${end}`, {
      get: () => segment[end], set: (p) => { segment[end] = p; }, radius: () => HANDLE_RADIUS,
    }, redraw);
  }
});
state.arcs.forEach((arc, i) => {
  figure.handle(`arc${i}-center`, {
    get: () => arc.center, set: (p) => { arc.center = p; }, radius: () => HANDLE_RADIUS,
  }, redraw);
  figure.handle(`arc${i}-start`, arcEnd(arc, 'start'), redraw);
  figure.handle(`arc${i}-end`, arcEnd(arc, 'end'), redraw);
});

fillLegend(document.getElementById('legend'), [
  {title: 'The step', entries: [
    {mark: 'disc', cls: 'ball a', text: 'the ball at the start'},
    {mark: 'arrow', cls: 'a', text: 'v: its movement during the step'},
    {mark: 'ring', cls: 'ball a ghost', text: 'the ball at the end of the step, if nothing is hit'},
    {mark: 'line', cls: 'wall', text: 'a segment or an arc'},
    {mark: 'line', cls: 'wall touched', text: 'the first one the ball touches'},
  ]},
  {title: 'The bounce', entries: [
    {mark: 'ring', cls: 'ball a outline', text: 'the ball at the contact'},
    {mark: 'dot', cls: 'contact', text: 'the contact point'},
    {mark: 'arrow', cls: 'a along', text: 'v along the normal'},
    {mark: 'arrow', cls: 'a across', text: 'v across it'},
    {mark: 'arrow', cls: 'a after', text: "v′: the ball's movement after the bounce"},
  ]},
]);

function redraw() {
  const result = attempt(() => {
    state.segments.forEach((segment, i) => scene.set_segment(i, segment));
    state.arcs.forEach((arc, i) => scene.set_arc(i, arc));
    return scene.solve(state.ball, state.move, restitution.value);
  });
  figure.update(() => { if (result) draw(result); });
  if (result) show(result);
}

const touched = (f, kind, i) => f.kind === kind && f.index === i;

function draw(f) {
  const {ball, move} = state;
  state.segments.forEach((s, i) => {
    figure.line(s.a, s.b, touched(f, carom.ShapeKind.segment, i) ? 'wall touched' : 'wall');
  });
  state.arcs.forEach((arc, i) => {
    figure.arc(arc, touched(f, carom.ShapeKind.arc, i) ? 'wall touched' : 'wall');
  });
  figure.circle(f.end, ball.radius, 'ball a ghost');
  figure.circle(ball.center, ball.radius, 'ball a');
  const hit = f.kind !== carom.ShapeKind.none;
  if (hit) {
    figure.circle(f.impact.a_at, ball.radius, 'ball a outline');
    figure.circle(f.impact.point, 0.12, 'contact');
  }
  figure.arrow(ball.center, move, 'a', 'v');
  if (!hit) return;
  const impact = f.impact;
  figure.arrow(impact.a_at, f.split.along, 'a along');
  figure.arrow(impact.a_at, f.split.across, 'a across');
  figure.arrow(impact.a_at, f.after.velocity, 'a after', 'v′');
}

function describe(f) {
  if (f.kind === carom.ShapeKind.segment) {
    return `segment ${f.index + 1}${f.at_end_point ? ', at an end point' : ''}`;
  }
  return `arc ${f.index + 1}`;
}

function show(f) {
  const texts = {
    ball: `${vec(state.ball.center)}, r ${num(state.ball.radius)}`,
    move: vec(state.move),
  };
  state.segments.forEach((s, i) => { texts[`segment${i}`] = `${vec(s.a)} to ${vec(s.b)}`; });
  state.arcs.forEach((arc, i) => {
    texts[`arc${i}`] = `${vec(arc.center)}, r ${num(arc.radius)}, ` +
                       `${num(arc.start_angle, 4)} to ${num(arc.end_angle, 4)} rad`;
  });
  if (f.kind === carom.ShapeKind.none) {
    texts.shape = 'nothing during the step';
  } else {
    const impact = f.impact;
    Object.assign(texts, {
      shape: describe(f),
      t: impact.overlapping ? '0 (it overlaps at the start)' : num(impact.t),
      a_at: vec(impact.a_at),
      point: vec(impact.point),
      normal: vec(impact.normal),
      split: `${vec(f.split.along)} / ${vec(f.split.across)}`,
      after: vec(f.after.velocity),
      impulse: num(f.after.impulse),
    });
  }
  fillReadout(texts);
}

// Handles and labels keep their size on screen, so they are placed again when the layout
// changes.
window.addEventListener('resize', redraw);
redraw();
document.body.dataset.ready = 'true';
