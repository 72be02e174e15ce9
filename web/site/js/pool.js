// "Pool": an aim line on a billiards table. The table is examples/billiards-frictionless.json
// (cushions as segments, six pockets, fifteen racked balls and the cue ball), loaded with carom's scene
// library, the cue ball at rest. Dragging sets the shot (direction from the cue ball towards the
// pointer, speed by the distance); carom answers where the cue ball first touches something
// (World::cast_ball, the cue ball left out), how the two balls leave a ball contact
// (carom::bounce) or the cue ball a cushion (carom::bounce_off_static), and where each goes next
// (cast_ball again). Shoot runs the table (carom::step_scene: pockets take balls) and lists the
// first contact beside the prediction. This page keeps the aim, stops the run and draws.
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const SCENE = 'billiards-frictionless.json';
const FRAME_TIME = 1 / 60;  // table time per frame: a time unit is a second
// No friction: balls never stop by themselves, so a shot runs this long (table time) at most.
const SHOT_SECONDS = 5;
const SPEED_PER_METRE = 5;  // a drag of 1 m from the cue ball shoots at 5 m/s
const MIN_SPEED = 0.1;
const MAX_SPEED = 8;        // m/s: a hard break
const RAIL = 0.12;          // m of rail drawn round the cloth
const DIRECTION_LENGTH = 0.2;  // m: the arrows of the balls' directions after the contact

const canvas = document.getElementById('table');
const message = document.getElementById('message');
const speedOutput = document.querySelector('output[for="speed"]');
const speedSlider = slider('speed', (value) => {
  if (!aim) return;
  aim = {...aim, speed: value};
  predict();
});

const text = await (await fetch(`examples/${SCENE}`)).text();
const sceneFile = JSON.parse(text);
const sceneBalls = sceneFile.balls;
// The names and the cue ball's spot are the scene file's; everything else is asked of carom.
const startNames = sceneBalls.map((b) => b.name ?? '');
const pocketNames = (sceneFile.pockets ?? []).map((q, k) => q.name ?? String(k));
const CUE_NAME = 'cue';
const headSpot = (() => {
  const [x, y] = sceneBalls[startNames.indexOf(CUE_NAME)].position;
  return {x, y};
})();

let world = null;
let names = [];
let cue = -1;        // the cue ball's index (a new one after it was potted and put back)
let cueRadius = 0;
let cueMass = 0;
let restitution = 1;
let cushions = [];
let pockets = [];
let cloth = null;    // the cushions' rectangle
let view = null;
let painter = null;
let aim = null;         // {direction (unit), speed}
let prediction = null;  // what carom answers for the aim (predict)
let dragging = false;
let pointer = null;     // the pointer while dragging, in world units
let running = false;
let shot = null;        // the last shot: when, what was predicted, what happened

function build() {
  if (world) world.delete();
  world = carom.load_scene(text, SCENE);
  names = [...startNames];
  cue = names.indexOf(CUE_NAME);
  world.set_velocity(cue, {x: 0, y: 0});  // the scene breaks at 6 m/s; here the user shoots
  cueRadius = world.radius(cue);
  cueMass = world.mass(cue);
  restitution = world.def().restitution;
  cushions = world.segments();
  pockets = world.pockets();
  const xs = cushions.flatMap((s) => [s.a.x, s.b.x]);
  const ys = cushions.flatMap((s) => [s.a.y, s.b.y]);
  cloth = {x0: Math.min(...xs), x1: Math.max(...xs), y0: Math.min(...ys), y1: Math.max(...ys)};
  view = {x: cloth.x0 - RAIL, y: cloth.y0 - RAIL, width: cloth.x1 - cloth.x0 + 2 * RAIL,
          height: cloth.y1 - cloth.y0 + 2 * RAIL};
  if (painter) painter.setView(view); else painter = new WorldCanvas(canvas, view);
  running = false;
  shot = null;
  predict();
}

// ---- the aim ----------------------------------------------------------------------------------

const scaled = (v, s) => ({x: v.x * s, y: v.y * s});
const unit = (v) => {
  const n = Math.hypot(v.x, v.y);
  return n > 0 ? scaled(v, 1 / n) : null;
};

// A cast long enough to cross the whole table.
function reach() { return Math.hypot(view.width, view.height); }

// Where a ball of radius r at `from` moving along `direction` goes first (carom's cast_ball),
// with the filter given; null without a direction.
function castFrom(from, r, direction, filter) {
  if (!direction) return null;
  const length = reach();
  const hit = world.cast_ball(from, r, scaled(direction, length), filter);
  return {...hit, distance: hit.fraction * length};
}

// carom's answers for the aim: the cast, and after a ball contact the two balls' velocities and
// where each goes next, after a cushion the cue ball's rebound and where it goes.
function predict() {
  prediction = null;
  if (!aim || running || cue < 0) return;
  const from = world.position(cue);
  const velocity = scaled(aim.direction, aim.speed);
  const hit = castFrom(from, cueRadius, aim.direction, {ignore: cue});
  const p = {from, velocity, speed: aim.speed, hit, time: hit.distance / aim.speed};
  // The normal points from what was hit back to the cue ball; bounce wants it from the cue ball
  // towards the other.
  const towards = scaled(hit.normal, -1);
  if (hit.kind === 'ball') {
    const object = hit.ball;
    const after = carom.bounce(velocity, cueMass, world.velocity(object), world.mass(object),
                               towards, restitution);
    p.object = object;
    p.objectFrom = world.position(object);
    p.objectRadius = world.radius(object);
    p.objectVelocity = after.velocity_b;
    p.cueVelocity = after.velocity_a;
    // The object ball's way on, the cue ball (which will have moved) left out; the cue ball's
    // from the ghost ball, the object ball (which leaves faster) left out.
    p.objectPath = castFrom(p.objectFrom, p.objectRadius, unit(after.velocity_b),
                            {ignore: object, accept: (i) => i !== cue});
    p.cuePath = castFrom(hit.center, cueRadius, unit(after.velocity_a),
                         {ignore: cue, accept: (i) => i !== object});
  } else if (hit.kind === 'wall') {
    p.cueVelocity = carom.bounce_off_static(velocity, cueMass, towards, restitution).velocity;
    p.cuePath = castFrom(hit.center, cueRadius, unit(p.cueVelocity), {ignore: cue});
  }
  prediction = p;
}

function setAim(direction, speed) {
  const d = unit(direction);
  if (!d) return;
  aim = {direction: d, speed: Math.min(MAX_SPEED, Math.max(MIN_SPEED, speed))};
  speedSlider.input.value = String(aim.speed);
  speedOutput.textContent = num(aim.speed, 3);
  predict();
}

// The aim from the cue ball towards point, its speed by the distance.
function aimTowards(point) {
  const from = world.position(cue);
  const d = {x: point.x - from.x, y: point.y - from.y};
  if (Math.hypot(d.x, d.y) <= cueRadius) return;  // on the cue ball: no direction yet
  setAim(d, Math.hypot(d.x, d.y) * SPEED_PER_METRE);
}

// ---- the shot ---------------------------------------------------------------------------------

function shoot() {
  if (running || !prediction) return;
  const p = prediction;
  attempt(() => world.set_velocity(cue, p.velocity));
  shot = {
    start: world.time(),
    cue,
    predicted: {kind: p.hit.kind, ball: p.hit.ball, pocket: p.hit.pocket, wall: p.hit.wall,
                time: p.time, point: p.hit.point, center: p.hit.center},
    first: null,
    potted: [],
    contacts: 0,
    ended: null,
  };
  running = true;
  prediction = null;
  message.textContent = '';
}

// The cue ball's part in a contact: what it met, or null when the contact is not the cue ball's.
function cueContact(c) {
  if (c.kind === 'ball' && (c.a === shot.cue || c.b === shot.cue)) {
    return {kind: 'ball', ball: c.a === shot.cue ? c.b : c.a, pocket: -1, wall: -1};
  }
  if (c.a !== shot.cue) return null;
  return {kind: c.kind, ball: -1, pocket: c.pocket, wall: c.wall};
}

function record(contacts) {
  for (const c of contacts) {
    ++shot.contacts;
    if (c.kind === 'pocket') shot.potted.push(c.a);
    if (shot.first) continue;
    const met = cueContact(c);
    if (met) shot.first = {...met, time: c.time - shot.start, point: c.point};
  }
}

// Stops every ball where it is; a potted cue ball comes back to its spot (or the nearest free
// place along the spot's line towards the head cushion). The aim is shown again.
function endShot(why) {
  if (!running) return;
  running = false;
  shot.ended = why;
  const balls = Array.from(world.snapshot());
  for (let i = 0; i < balls.length / 4; ++i) {
    if (balls[4 * i + 2] > 0) world.set_velocity(i, {x: 0, y: 0});
  }
  if (balls[4 * cue + 2] === 0) respotCue();
  predict();
}

function respotCue() {
  for (let k = 0; k < 40; ++k) {
    const spot = {x: headSpot.x - k * cueRadius, y: headSpot.y};
    // Touching counts as meeting, so a place 10⁻⁹ m clear of every ball is looked for.
    if (world.balls_in_circle(spot, cueRadius * (1 + 1e-9), {}).length) continue;
    const index = attempt(() => world.add_ball(spot, {x: 0, y: 0}, cueRadius, cueMass));
    if (index === undefined) continue;
    cue = index;
    names[index] = CUE_NAME;
    message.textContent = 'The cue ball was potted: it is back on its spot.';
    return;
  }
  cue = -1;
  message.textContent = 'The cue ball was potted and its spot is taken: rack again.';
}

// ---- drawing ----------------------------------------------------------------------------------

const WOOD = '#6b4423';
const CLOTH = '#1f7a4a';
const CUSHION = '#145a34';
const AIM = '#ffffff';
const OBJECT_LINE = '#ffd54f';
const CUE_LINE = '#b3e5fc';

function disc(c, p, r, fill, stroke) {
  c.beginPath();
  c.arc(painter.px(p.x), painter.py(p.y), r * painter.scale, 0, 2 * Math.PI);
  if (fill) {
    c.fillStyle = fill;
    c.fill();
  }
  if (stroke) {
    c.strokeStyle = stroke;
    c.stroke();
  }
}

function line(c, a, b, colour, widthPx, dash = []) {
  const ratio = window.devicePixelRatio || 1;
  c.save();
  c.strokeStyle = colour;
  c.lineWidth = widthPx * ratio;
  c.setLineDash(dash.map((d) => d * ratio));
  c.beginPath();
  c.moveTo(painter.px(a.x), painter.py(a.y));
  c.lineTo(painter.px(b.x), painter.py(b.y));
  c.stroke();
  c.restore();
}

// A line from a to b with an arrowhead at b.
function arrow(c, a, b, colour, widthPx, dash = []) {
  line(c, a, b, colour, widthPx, dash);
  const ratio = window.devicePixelRatio || 1;
  const [ax, ay, bx, by] = [painter.px(a.x), painter.py(a.y), painter.px(b.x), painter.py(b.y)];
  const length = Math.hypot(bx - ax, by - ay);
  if (length < 1) return;
  const [ux, uy] = [(bx - ax) / length, (by - ay) / length];
  const size = 8 * ratio;
  c.fillStyle = colour;
  c.beginPath();
  c.moveTo(bx, by);
  c.lineTo(bx - size * ux - size * 0.45 * uy, by - size * uy + size * 0.45 * ux);
  c.lineTo(bx - size * ux + size * 0.45 * uy, by - size * uy - size * 0.45 * ux);
  c.closePath();
  c.fill();
}

function drawBall(c, i, x, y, r, colours) {
  const ratio = window.devicePixelRatio || 1;
  const p = {x, y};
  c.lineWidth = ratio;
  if (i === cue) {
    disc(c, p, r, '#f8f8f0', '#222');
    return;
  }
  const colour = colours[i] || '#999';
  const number = Number(names[i]);
  if (number >= 9) {
    // A stripe: white with a band of the colour across it.
    disc(c, p, r, '#f8f8f0');
    c.save();
    c.clip();
    c.fillStyle = colour;
    c.fillRect(painter.px(x - r), painter.py(y + 0.55 * r), 2 * r * painter.scale,
               1.1 * r * painter.scale);
    c.restore();
    disc(c, p, r, null, '#222');
  } else {
    disc(c, p, r, colour, '#222');
  }
  if (names[i]) {
    disc(c, p, 0.5 * r, '#f8f8f0');
    painter.label(names[i], p, '#111', Math.max(6, 0.55 * r * painter.scale / ratio));
  }
}

// A ball's way after the contact: an arrow along its velocity, DIRECTION_LENGTH long, and a thin
// line on to where it would meet something next, with its outline (radius r) there.
function departure(c, from, velocity, path, r, colour) {
  if (!velocity || !path) return;
  const d = unit(velocity);
  if (path.distance > DIRECTION_LENGTH) line(c, from, path.center, colour, 1, [4, 4]);
  ghost(c, path.center, r, colour, 1);
  arrow(c, from, {x: from.x + d.x * DIRECTION_LENGTH, y: from.y + d.y * DIRECTION_LENGTH},
        colour, 2.5);
}

// A dashed outline of a ball of radius r at p.
function ghost(c, p, r, colour, widthPx) {
  const ratio = window.devicePixelRatio || 1;
  c.save();
  c.setLineDash([4 * ratio, 3 * ratio]);
  c.lineWidth = widthPx * ratio;
  disc(c, p, r, null, colour);
  c.restore();
}

function drawAim(c) {
  const p = prediction;
  const {hit} = p;
  if (dragging && pointer) line(c, p.from, pointer, 'rgba(255,255,255,0.35)', 1, [2, 3]);
  line(c, p.from, hit.center, AIM, 1.5, [6, 4]);
  if (hit.kind === 'pocket') disc(c, pockets[hit.pocket], pockets[hit.pocket].radius, null, AIM);
  if (p.objectPath) {
    departure(c, p.objectFrom, p.objectVelocity, p.objectPath, p.objectRadius, OBJECT_LINE);
  }
  departure(c, hit.center, p.cueVelocity, p.cuePath, cueRadius, CUE_LINE);
  // The ghost ball (the cue ball where it first touches something) and the touching point.
  ghost(c, hit.center, cueRadius, AIM, 1.5);
  disc(c, hit.point, 0.18 * cueRadius, '#ff5252');
}

function draw() {
  painter.resize();
  const c = painter.context;
  const s = painter.scale;
  c.fillStyle = WOOD;
  c.fillRect(0, 0, canvas.width, canvas.height);
  c.fillStyle = CLOTH;
  c.fillRect(painter.px(cloth.x0), painter.py(cloth.y1), (cloth.x1 - cloth.x0) * s,
             (cloth.y1 - cloth.y0) * s);
  for (const pocket of pockets) disc(c, pocket, pocket.radius, '#111');
  painter.segments(cushions, CUSHION, 4);
  const balls = Array.from(world.snapshot());
  const colours = world.colors();
  for (let i = 0; i < balls.length / 4; ++i) {
    const [x, y, r] = [balls[4 * i], balls[4 * i + 1], balls[4 * i + 2]];
    if (r > 0) drawBall(c, i, x, y, r, colours);
  }
  if (prediction) drawAim(c);
  painter.frame();
}

// ---- the readout ------------------------------------------------------------------------------

// A cushion by where it lies: bottom-left, ..., left, right (a box's four walls come first in
// the World's wall ids, then the scene's segments in order).
function cushionName(wall) {
  const s = cushions[wall - (world.def().boundary === carom.Boundary.box ? 4 : 0)];
  if (!s) return `wall ${wall}`;
  const middle = (cloth.x0 + cloth.x1) / 2;
  if (s.a.x === s.b.x) return s.a.x < middle ? 'left' : 'right';
  const side = (s.a.y + s.b.y) / 2 < (cloth.y0 + cloth.y1) / 2 ? 'bottom' : 'top';
  return `${side}-${(s.a.x + s.b.x) / 2 < middle ? 'left' : 'right'}`;
}

function what(hit) {
  if (!hit) return '—';
  switch (hit.kind) {
    case 'ball': return `ball ${names[hit.ball] || hit.ball}`;
    case 'pocket': return `pocket ${pocketNames[hit.pocket]}`;
    case 'wall': return hit.boundary ? 'the table\'s edge' : `${cushionName(hit.wall)} cushion`;
    default: return 'nothing';
  }
}

function report() {
  const p = prediction;
  const balls = Array.from(world.snapshot());
  let onTable = 0;
  for (let i = 2; i < balls.length; i += 4) if (balls[i] > 0) ++onTable;
  let state = 'aim: drag from the cue ball';
  if (running) state = `running, ${num(world.time() - shot.start, 3)} s`;
  else if (aim) state = 'ready';
  let first = '—';
  if (shot?.first) {
    const expected = shot.predicted;
    const same = shot.first.kind === expected.kind && shot.first.ball === expected.ball &&
                 shot.first.pocket === expected.pocket && shot.first.wall === expected.wall;
    first = `${what(shot.first)} at ${num(shot.first.time, 6)} s ` +
            `(predicted ${what(expected)} at ${num(expected.time, 6)} s${same ? '' : ': differs'})`;
  }
  fillReadout({
    target: p ? what(p.hit) + (p.hit.overlapping ? ' (touching it now)' : '') : '—',
    ghost: p ? vec(p.hit.center, 5) : '—',
    distance: p ? `${num(p.hit.distance, 5)} m, ${num(p.time, 4)} s at ${num(p.speed, 3)} m/s`
                : '—',
    object_path: p?.objectPath ? what(p.objectPath) : '—',
    cue_path: p?.cuePath ? what(p.cuePath) : '—',
    shot: state,
    first,
    potted: shot?.potted.length ? shot.potted.map((i) => names[i] || i).join(', ') : '—',
    balls: String(onTable),
  });
}

// ---- running ----------------------------------------------------------------------------------

function frame() {
  requestAnimationFrame(frame);
  if (running) {
    attempt(() => world.step(FRAME_TIME));
    record(world.step_contacts());
    if (world.time() - shot.start >= SHOT_SECONDS) endShot('time');
    else if (world.kinetic_energy() === 0) endShot('rest');
  }
  draw();
  report();
}

function worldPoint(event) {
  const box = canvas.getBoundingClientRect();
  return {x: view.x + (event.clientX - box.left) / box.width * view.width,
          y: view.y + view.height - (event.clientY - box.top) / box.height * view.height};
}

canvas.addEventListener('pointerdown', (event) => {
  event.preventDefault();
  if (running) {
    endShot('click');
    return;
  }
  if (cue < 0) return;
  canvas.setPointerCapture(event.pointerId);
  dragging = true;
  pointer = worldPoint(event);
  aimTowards(pointer);
});
canvas.addEventListener('pointermove', (event) => {
  if (!dragging) return;
  pointer = worldPoint(event);
  aimTowards(pointer);
});
const letGo = () => {
  dragging = false;
  pointer = null;
};
canvas.addEventListener('pointerup', letGo);
canvas.addEventListener('pointercancel', letGo);

document.getElementById('shoot').addEventListener('click', shoot);
document.getElementById('stop').addEventListener('click', () => endShot('stop'));
document.getElementById('rack').addEventListener('click', () => {
  build();
  message.textContent = '';
});
// The space bar shoots, except on a button or a control, where it already means something.
document.addEventListener('keydown', (event) => {
  if (event.key !== ' ' || event.repeat) return;
  if (event.target instanceof HTMLButtonElement || event.target instanceof HTMLInputElement) return;
  event.preventDefault();
  shoot();
});

// For the tests (web/tests/pool.test.mjs).
window.caromPool = {
  get world() { return world; },
  get cue() { return cue; },
  get names() { return [...names]; },
  pocketNames,
  get restitution() { return restitution; },
  get prediction() { return prediction; },
  get running() { return running; },
  get shot() { return shot; },
  // The aim as a drag would set it: direction (any length) and speed in m/s.
  aim(direction, speed) {
    setAim(direction, speed);
    return prediction;
  },
  shoot,
  // Where world point p is on the screen, in CSS pixels (for a drag).
  screenPoint(p) {
    const box = canvas.getBoundingClientRect();
    return {x: box.left + (p.x - view.x) / view.width * box.width,
            y: box.top + (view.y + view.height - p.y) / view.height * box.height};
  },
};

build();
setAim({x: 1, y: 0}, speedSlider.value);
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
