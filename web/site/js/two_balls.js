// "Two moving balls": the tutorial's figure. The state is the inputs only; carom computes the
// contact, the split along the line of centres and the bounce (carom::web::two_balls_figure).
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {fillReadout, slider} from './sliders.js';
import {Figure, fillLegend} from './svg_figure.js';

// The case `carom sweep` draws by default (make run).
const state = {
  a: {center: {x: 0, y: 0}, radius: 1},
  move_a: {x: 6, y: 2},
  b: {center: {x: 8, y: 3}, radius: 1.5},
  move_b: {x: -4, y: -1},
};

const figure = new Figure(document.getElementById('figure'), {x: -4, y: -4, width: 18, height: 13});
const radiusA = slider('radius-a', (r) => { state.a.radius = r; redraw(); });
const radiusB = slider('radius-b', (r) => { state.b.radius = r; redraw(); });
const massA = slider('mass-a', redraw);
const massB = slider('mass-b', redraw);
const restitution = slider('restitution', redraw);
state.a.radius = radiusA.value;
state.b.radius = radiusB.value;

const plus = (p, v) => ({x: p.x + v.x, y: p.y + v.y});
const minus = (p, q) => ({x: p.x - q.x, y: p.y - q.y});
const HANDLE_RADIUS = 0.45;  // world units: big enough to catch with a finger

figure.handle('a', {get: () => state.a.center, set: (p) => { state.a.center = p; },
                    radius: () => state.a.radius, cls: 'ball-handle', ball: true}, redraw);
figure.handle('b', {get: () => state.b.center, set: (p) => { state.b.center = p; },
                    radius: () => state.b.radius, cls: 'ball-handle', ball: true}, redraw);
figure.handle('va-end', {get: () => plus(state.a.center, state.move_a),
                         set: (p) => { state.move_a = minus(p, state.a.center); },
                         radius: () => HANDLE_RADIUS}, redraw);
figure.handle('vb-end', {get: () => plus(state.b.center, state.move_b),
                         set: (p) => { state.move_b = minus(p, state.b.center); },
                         radius: () => HANDLE_RADIUS}, redraw);

// In two parts, as `carom sweep --svg` draws the case: the step, then the bounce.
fillLegend(document.getElementById('legend'), [
  {title: 'The step', entries: [
    {mark: 'disc', cls: 'ball a', text: 'A at the start'},
    {mark: 'disc', cls: 'ball b', text: 'B at the start'},
    {mark: 'arrow', cls: 'a', text: "va: A's movement during the step"},
    {mark: 'arrow', cls: 'b', text: "vb: B's movement during the step"},
    {mark: 'arrow', cls: 'v3', text: "v3 = va − vb: A's movement seen from B"},
    {mark: 'ring', cls: 'ball a ghost', text: 'A at the end of the step, if nothing is hit'},
    {mark: 'ring', cls: 'ball b ghost', text: 'B at the end of the step, if nothing is hit'},
    {mark: 'ring', cls: 'ball v3 outline', text: 'A at the contact, seen from B'},
  ]},
  {title: 'The bounce', entries: [
    {mark: 'ring', cls: 'ball a outline', text: 'A at the contact'},
    {mark: 'ring', cls: 'ball b outline', text: 'B at the contact'},
    {mark: 'dot', cls: 'contact', text: 'the contact point'},
    {mark: 'line', cls: 'centres', text: 'the line of centres'},
    {mark: 'arrow', cls: 'a along', text: 'va along the line of centres'},
    {mark: 'arrow', cls: 'a across', text: 'va across it'},
    {mark: 'arrow', cls: 'b along', text: 'vb along the line of centres'},
    {mark: 'arrow', cls: 'b across', text: 'vb across it'},
    {mark: 'arrow', cls: 'a after', text: "va′: A's movement after the bounce"},
    {mark: 'arrow', cls: 'b after', text: "vb′: B's movement after the bounce"},
  ]},
]);

function redraw() {
  const input = {...state, mass_a: massA.value, mass_b: massB.value,
                 restitution: restitution.value};
  const result = attempt(() => carom.two_balls_figure(input));
  figure.update(() => { if (result) draw(result); });
  if (result) show(result);
}

function draw(f) {
  const {a, b} = state;
  figure.circle(f.a_end, a.radius, 'ball a ghost');
  figure.circle(f.b_end, b.radius, 'ball b ghost');
  figure.circle(a.center, a.radius, 'ball a');
  figure.circle(b.center, b.radius, 'ball b');
  const impact = f.impact;
  if (impact.hit) {
    // In B's frame A travels along v3 and touches the standing B at a_relative_at (the
    // tutorial's p4).
    figure.circle(f.a_relative_at, a.radius, 'ball v3 outline');
    figure.circle(impact.a_at, a.radius, 'ball a outline');
    figure.circle(impact.b_at, b.radius, 'ball b outline');
    figure.line(impact.a_at, impact.b_at, 'centres');
    figure.circle(impact.point, 0.12, 'contact');
  }
  // Arrows after the shapes: their labels keep clear of each other in this order, the
  // movements first.
  figure.arrow(a.center, state.move_a, 'a', 'va');
  figure.arrow(b.center, state.move_b, 'b', 'vb');
  figure.arrow(a.center, f.v3, 'v3', 'v3');
  if (!impact.hit) return;
  figure.arrow(impact.a_at, f.split_a.along, 'a along');
  figure.arrow(impact.a_at, f.split_a.across, 'a across');
  figure.arrow(impact.b_at, f.split_b.along, 'b along');
  figure.arrow(impact.b_at, f.split_b.across, 'b across');
  figure.arrow(impact.a_at, f.after.velocity_a, 'a after', 'va′');
  figure.arrow(impact.b_at, f.after.velocity_b, 'b after', 'vb′');
}

function show(f) {
  const impact = f.impact;
  const texts = {
    a: `${vec(state.a.center)}, r ${num(state.a.radius)}`,
    va: vec(state.move_a),
    b: `${vec(state.b.center)}, r ${num(state.b.radius)}`,
    vb: vec(state.move_b),
    v3: vec(f.v3),
  };
  if (impact.hit) {
    Object.assign(texts, {
      t: impact.overlapping ? '0 (they overlap at the start)' : num(impact.t),
      a_at: vec(impact.a_at),
      b_at: vec(impact.b_at),
      normal: vec(impact.normal),
      point: vec(impact.point),
      split_a: `${vec(f.split_a.along)} / ${vec(f.split_a.across)}`,
      split_b: `${vec(f.split_b.along)} / ${vec(f.split_b.across)}`,
      va_after: vec(f.after.velocity_a),
      vb_after: vec(f.after.velocity_b),
      impulse: num(f.after.impulse),
    });
  } else {
    texts.t = impact.overlapping ? 'no contact: they overlap and separate'
                                 : 'no contact during the step';
  }
  fillReadout(texts);
}

// Handles and labels keep their size on screen, so they are placed again when the layout
// changes.
window.addEventListener('resize', redraw);
redraw();
document.body.dataset.ready = 'true';
