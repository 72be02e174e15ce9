// "Pool": a shot on a table with friction. The table is examples/billiards.json (cushions as
// segments, six pockets, fifteen racked balls and the cue ball; its cloth slides, rolls and spins
// the balls, docs/pool.md), loaded with carom's scene library without its break shot. Dragging
// sets the aim (direction from the cue ball towards the pointer, the cue's speed by the
// distance); the ball diagram sets where the tip meets the cue ball (side and top or back spin).
// carom answers in two ways: the ghost ball, where the cue ball first touches something along
// the aim (World::cast_ball, the cue ball left out: a level cue sends it straight), and the whole
// shot, run to rest on a copy of the world (DrawnWorld::copy, World::save and load) with the same
// strike and the same frames the page then runs: every ball's path and resting place. Shoot runs
// the table itself frame by frame until every ball rests and says whether it went exactly as
// predicted. This page keeps the aim, runs the frames and draws.
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const SCENE = 'billiards.json';
const FRAME_TIME = 1 / 60;  // table time per frame: a time unit is a second
// A shot that has not come to rest after this many frames (a minute of table time) is stopped.
const MAX_FRAMES = 3600;
const SPEED_PER_METRE = 4;  // a drag of 1 m from the cue ball moves the cue at 4 m/s
const MIN_SPEED = 0.1;
const MAX_SPEED = 7;        // m/s of the cue: the cue ball leaves at about 1.5 times it
const TIP_LIMIT = 0.5;      // the tip within half the radius of the centre: farther, it miscues
const TIP_STEP = 0.05;      // an arrow key moves the tip this share of the radius
const RAIL = 0.12;          // m of rail drawn round the cloth

const canvas = document.getElementById('table');
const tipCanvas = document.getElementById('tip');
const message = document.getElementById('message');
const speedOutput = document.querySelector('output[for="speed"]');
const speedSlider = slider('speed', (value) => {
  if (!aim) return;
  aim = {...aim, speed: value};
  predict();
});

const text = await (await fetch(`examples/${SCENE}`)).text();
const sceneFile = JSON.parse(text);
// The user strikes the cue ball here: the scene's own break shot is left out.
delete sceneFile.shots;
const tableText = JSON.stringify(sceneFile);
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
let cushions = [];
let pockets = [];
let cloth = null;    // the cushions' rectangle
let view = null;
let painter = null;
let aim = null;             // {direction (unit), speed of the cue}
let tip = {side: 0, height: 0};  // where the tip meets the cue ball, in shares of its radius
let prediction = null;      // what carom answers for the aim and tip (predict)
let dragging = false;
let pointer = null;         // the pointer while dragging, in world units
let running = false;
let shot = null;            // the last shot: what was predicted and what happened

function build() {
  if (world) world.delete();
  world = carom.load_scene(tableText, SCENE);
  names = [...startNames];
  cue = names.indexOf(CUE_NAME);
  cueRadius = world.radius(cue);
  cueMass = world.mass(cue);
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

// The cue's strike for the aim and the tip: carom::CueStrike's fields (a level cue).
function strikeOf(a) {
  return {speed: a.speed, direction: Math.atan2(a.direction.y, a.direction.x),
          side: tip.side * cueRadius, height: tip.height * cueRadius};
}

// What one step's contacts say about a shot: the cue ball's first contact (times from the
// shot's start), the balls the pockets took, and how many contacts there were.
function tally(record, contacts, start) {
  for (const c of contacts) {
    ++record.contacts;
    if (c.kind === 'pocket') record.potted.push(c.a);
    if (record.first) continue;
    let met = null;
    if (c.kind === 'ball' && (c.a === record.cue || c.b === record.cue)) {
      met = {kind: 'ball', ball: c.a === record.cue ? c.b : c.a, pocket: -1, wall: -1};
    } else if (c.a === record.cue) {
      met = {kind: c.kind, ball: -1, pocket: c.pocket, wall: c.wall};
    }
    if (met) record.first = {...met, time: c.time - start, point: c.point, normal: c.normal};
  }
}

// Where each ball is now, by index (null for a ball a pocket took): the places a shot ends in.
function places(w) {
  const balls = Array.from(w.snapshot());  // a copy: position() may move the module's memory
  const out = [];
  for (let i = 0; i < balls.length / 4; ++i) out.push(balls[4 * i + 2] > 0 ? w.position(i) : null);
  return out;
}

// The shot run to rest on a copy of the world, frame by frame as shoot() runs it: the cue ball's
// launch, its first contact, every ball's path (its place after each frame, the first at the
// strike, until a pocket takes it; for drawing) and resting place.
function tryShot(strike) {
  const trial = world.copy();
  try {
    trial.strike(cue, strike);
    const start = trial.time();
    const launch = {velocity: trial.velocity(cue), spin: trial.spin(cue),
                    state: trial.motion_state(cue)};
    const record = {cue, first: null, potted: [], contacts: 0};
    const paths = places(trial).map((p) => (p ? [p] : []));
    let frames = 0;
    while (!trial.at_rest() && frames < MAX_FRAMES) {
      trial.step(FRAME_TIME);
      ++frames;
      const contacts = trial.step_contacts();
      tally(record, contacts, start);
      // A potted ball's path ends in its pocket.
      for (const c of contacts) if (c.kind === 'pocket') paths[c.a].push(c.point);
      const balls = trial.snapshot();
      for (let i = 0; i < paths.length; ++i) {
        if (balls[4 * i + 2] > 0) paths[i].push({x: balls[4 * i], y: balls[4 * i + 1]});
      }
    }
    return {launch, ...record, paths, frames, rests: trial.at_rest(), end: places(trial)};
  } finally {
    trial.delete();
  }
}

// carom's answers for the aim and the tip: the cast along the aim (the ghost ball) and the shot
// run to rest on a copy.
function predict() {
  prediction = null;
  if (!aim || running || cue < 0) return;
  const from = world.position(cue);
  const length = Math.hypot(view.width, view.height);  // a cast across the whole table
  const hit = world.cast_ball(from, cueRadius, scaled(aim.direction, length), {ignore: cue});
  hit.distance = hit.fraction * length;
  const strike = strikeOf(aim);
  prediction = {from, velocity: scaled(aim.direction, aim.speed), speed: aim.speed, strike, hit,
                ...attempt(() => tryShot(strike))};
}

function setAim(direction, speed) {
  const d = unit(direction);
  if (!d) return;
  aim = {direction: d, speed: Math.min(MAX_SPEED, Math.max(MIN_SPEED, speed))};
  speedSlider.input.value = String(aim.speed);
  speedOutput.textContent = num(aim.speed, 3);
  predict();
}

// The aim from the cue ball towards point, the cue's speed by the distance.
function aimTowards(point) {
  const from = world.position(cue);
  const d = {x: point.x - from.x, y: point.y - from.y};
  if (Math.hypot(d.x, d.y) <= cueRadius) return;  // on the cue ball: no direction yet
  setAim(d, Math.hypot(d.x, d.y) * SPEED_PER_METRE);
}

// The tip at (side, height) shares of the radius, brought within TIP_LIMIT of the centre.
function setTip(side, height) {
  const r = Math.hypot(side, height);
  const s = r > TIP_LIMIT ? TIP_LIMIT / r : 1;
  tip = {side: side * s, height: height * s};
  drawTip();
  predict();
}

// ---- the shot ---------------------------------------------------------------------------------

function shoot() {
  if (running || !prediction) return;
  const p = prediction;
  attempt(() => world.strike(cue, p.strike));
  shot = {start: world.time(), cue, predicted: p, first: null, potted: [], contacts: 0, frames: 0,
          states: new Set(), ended: null, asPredicted: null};
  running = true;
  prediction = null;
  message.textContent = '';
}

// Ends the shot: at rest by itself, or stopped (a click, Stop, or a minute gone) with every ball
// held still where it is, spin and all. A potted cue ball comes back to its spot (or the nearest
// free place along the spot's line towards the head cushion). The aim is shown again.
function endShot(why) {
  if (!running) return;
  running = false;
  shot.ended = why;
  shot.end = places(world);
  const p = shot.predicted;
  shot.asPredicted = why === 'rest' && shot.frames === p.frames &&
                     shot.contacts === p.contacts &&
                     shot.end.every((q, i) => (q === null ? p.end[i] === null
                                                          : p.end[i] && q.x === p.end[i].x &&
                                                            q.y === p.end[i].y));
  if (why !== 'rest') {
    shot.end.forEach((q, i) => {
      if (!q) return;
      world.set_velocity(i, {x: 0, y: 0});
      world.set_spin(i, {x: 0, y: 0, z: 0});
    });
  }
  if (shot.end[cue] === null) respotCue();
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

// A dashed outline of a ball of radius r at p.
function ghost(c, p, r, colour, widthPx) {
  const ratio = window.devicePixelRatio || 1;
  c.save();
  c.setLineDash([4 * ratio, 3 * ratio]);
  c.lineWidth = widthPx * ratio;
  disc(c, p, r, null, colour);
  c.restore();
}


// A ball's predicted path, a line through its place at every frame, and a dashed outline where
// it comes to rest (none for a ball a pocket takes).
function drawPath(c, path, end, r, colour) {
  if (path.length < 2) return;
  const ratio = window.devicePixelRatio || 1;
  c.save();
  c.strokeStyle = colour;
  c.lineWidth = 1.5 * ratio;
  c.beginPath();
  c.moveTo(painter.px(path[0].x), painter.py(path[0].y));
  for (const q of path) c.lineTo(painter.px(q.x), painter.py(q.y));
  c.stroke();
  c.restore();
  if (end) ghost(c, end, r, colour, 1);
}

function drawPrediction(c) {
  const p = prediction;
  const {hit} = p;
  if (dragging && pointer) line(c, p.from, pointer, 'rgba(255,255,255,0.35)', 1, [2, 3]);
  const balls = world.snapshot();
  p.paths.forEach((path, i) => {
    drawPath(c, path, p.end[i], balls[4 * i + 2], i === cue ? CUE_LINE : OBJECT_LINE);
  });
  // The cast along the aim: the ghost ball and the touching point, where the cue ball gets to it.
  if (!sameContact(p.first, hit)) return;
  line(c, p.from, hit.center, AIM, 1.5, [6, 4]);
  if (hit.kind === 'pocket') disc(c, pockets[hit.pocket], pockets[hit.pocket].radius, null, AIM);
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
  if (prediction) drawPrediction(c);
  const balls = Array.from(world.snapshot());
  const colours = world.colors();
  for (let i = 0; i < balls.length / 4; ++i) {
    const [x, y, r] = [balls[4 * i], balls[4 * i + 1], balls[4 * i + 2]];
    if (r > 0) drawBall(c, i, x, y, r, colours);
  }
  painter.frame();
}

// The cue ball seen by the player: the tip's place on it, and the circle it must stay within.
function drawTip() {
  const ratio = window.devicePixelRatio || 1;
  const box = tipCanvas.getBoundingClientRect();
  tipCanvas.width = Math.max(1, Math.round(box.width * ratio));
  tipCanvas.height = Math.max(1, Math.round(box.height * ratio));
  const c = tipCanvas.getContext('2d');
  const [cx, cy] = [tipCanvas.width / 2, tipCanvas.height / 2];
  const r = 0.45 * Math.min(tipCanvas.width, tipCanvas.height);
  c.clearRect(0, 0, tipCanvas.width, tipCanvas.height);
  c.lineWidth = ratio;
  c.fillStyle = '#f8f8f0';
  c.strokeStyle = '#222';
  c.beginPath();
  c.arc(cx, cy, r, 0, 2 * Math.PI);
  c.fill();
  c.stroke();
  c.setLineDash([3 * ratio, 3 * ratio]);
  c.strokeStyle = '#999';
  c.beginPath();
  c.arc(cx, cy, TIP_LIMIT * r, 0, 2 * Math.PI);
  c.moveTo(cx - r, cy);
  c.lineTo(cx + r, cy);
  c.moveTo(cx, cy - r);
  c.lineTo(cx, cy + r);
  c.stroke();
  c.setLineDash([]);
  c.fillStyle = '#1565c0';
  c.beginPath();
  c.arc(cx + tip.side * r, cy - tip.height * r, 0.12 * r, 0, 2 * Math.PI);
  c.fill();
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
  if (!hit) return 'nothing: the cue ball stops first';
  switch (hit.kind) {
    case 'ball': return `ball ${names[hit.ball] || hit.ball}`;
    case 'pocket': return `pocket ${pocketNames[hit.pocket]}`;
    case 'wall': return hit.boundary ? 'the table\'s edge' : `${cushionName(hit.wall)} cushion`;
    default: return 'nothing';
  }
}

// Whether a contact met the same thing as a hit (or another contact).
function sameContact(a, b) {
  return Boolean(a && b) && a.kind === b.kind && a.ball === b.ball && a.pocket === b.pocket &&
         a.wall === b.wall;
}

function tipText() {
  const part = (value, plus, minus) =>
    (Math.abs(value) < 5e-3 ? '' : `${num(Math.abs(value), 2)} R ${value > 0 ? plus : minus}`);
  const parts = [part(tip.side, 'right', 'left'), part(tip.height, 'above', 'below')];
  return parts.filter(Boolean).join(', ') || 'centre';
}

function restText(p) {
  const potted = p.potted.length ? `; pots ${p.potted.map((i) => names[i] || i).join(', ')}` : '';
  const rest = p.rests ? `rest after ${num(p.frames * FRAME_TIME, 3)} s`
                       : `still moving after ${num(p.frames * FRAME_TIME, 3)} s`;
  return `${p.contacts} contacts, ${rest}${potted}`;
}

function report() {
  const p = prediction;
  const balls = Array.from(world.snapshot());
  let onTable = 0;
  for (let i = 2; i < balls.length; i += 4) if (balls[i] > 0) ++onTable;
  let state = 'aim: drag from the cue ball';
  if (running) state = `running, ${num(world.time() - shot.start, 3)} s`;
  else if (shot?.ended) state = shot.ended === 'rest' ? 'every ball at rest' : `stopped (${shot.ended})`;
  else if (aim) state = 'ready';
  let first = '—';
  if (shot?.first) {
    const expected = shot.predicted.first;
    const same = sameContact(shot.first, expected) && shot.first.time === expected.time;
    first = `${what(shot.first)} at ${num(shot.first.time, 6)} s ` +
            `(predicted ${what(expected)}${expected ? ` at ${num(expected.time, 6)} s` : ''}` +
            `${same ? '' : ': differs'})`;
  }
  let motion = '—';
  if (running || shot?.ended) {
    const counts = {sliding: 0, rolling: 0, spinning: 0, stationary: 0};
    for (let i = 0; i < balls.length / 4; ++i) {
      if (balls[4 * i + 2] > 0) ++counts[world.motion_state(i)];
    }
    motion = Object.entries(counts).map(([k, v]) => `${v} ${k}`).join(', ');
  }
  let predicted = '—';
  if (shot?.asPredicted !== null && shot?.asPredicted !== undefined) {
    predicted = shot.asPredicted ? 'yes: every ball where the prediction put it, to the bit'
                                 : 'no';
  }
  fillReadout({
    target: p ? what(p.first) : '—',
    ghost: p && sameContact(p.first, p.hit) ? vec(p.hit.center, 5) : '—',
    distance: p?.first ? `${num(p.hit.distance, 5)} m, after ${num(p.first.time, 4)} s` : '—',
    launch: p ? `${num(Math.hypot(p.launch.velocity.x, p.launch.velocity.y), 3)} m/s, ` +
                `${p.launch.state}` : '—',
    tip: tipText(),
    prediction: p ? restText(p) : '—',
    shot: state,
    first,
    motion,
    as_predicted: predicted,
    potted: shot?.potted.length ? shot.potted.map((i) => names[i] || i).join(', ') : '—',
    balls: String(onTable),
  });
}

// ---- running ----------------------------------------------------------------------------------

function frame() {
  requestAnimationFrame(frame);
  if (running) {
    attempt(() => world.step(FRAME_TIME));
    ++shot.frames;
    tally(shot, world.step_contacts(), shot.start);
    const balls = Array.from(world.snapshot());
    for (let i = 0; i < balls.length / 4; ++i) {
      if (balls[4 * i + 2] > 0) shot.states.add(world.motion_state(i));
    }
    if (world.at_rest()) endShot('rest');
    else if (shot.frames >= MAX_FRAMES) endShot('time');
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

// The tip: pressed or dragged on the ball diagram, or moved with the arrow keys.
function tipAt(event) {
  const box = tipCanvas.getBoundingClientRect();
  const r = 0.45 * Math.min(box.width, box.height);
  setTip((event.clientX - box.left - box.width / 2) / r,
         (box.top + box.height / 2 - event.clientY) / r);
}
let tipDragging = false;
tipCanvas.addEventListener('pointerdown', (event) => {
  event.preventDefault();
  tipCanvas.setPointerCapture(event.pointerId);
  tipDragging = true;
  tipAt(event);
});
tipCanvas.addEventListener('pointermove', (event) => { if (tipDragging) tipAt(event); });
for (const type of ['pointerup', 'pointercancel']) {
  tipCanvas.addEventListener(type, () => { tipDragging = false; });
}
const TIP_KEYS = {ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1]};
tipCanvas.addEventListener('keydown', (event) => {
  if (event.key === 'Home') {
    event.preventDefault();
    setTip(0, 0);
    return;
  }
  const move = TIP_KEYS[event.key];
  if (!move) return;
  event.preventDefault();
  setTip(tip.side + move[0] * TIP_STEP, tip.height + move[1] * TIP_STEP);
});
document.getElementById('centre-tip').addEventListener('click', () => setTip(0, 0));

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
window.addEventListener('resize', () => drawTip());

// For the tests (web/tests/pool.test.mjs).
window.caromPool = {
  get world() { return world; },
  get cue() { return cue; },
  get names() { return [...names]; },
  pocketNames,
  get prediction() { return prediction; },
  get running() { return running; },
  // The last shot, its set of motion states seen as a list.
  get shot() { return shot && {...shot, states: [...shot.states]}; },
  get tip() { return {...tip}; },
  frameTime: FRAME_TIME,
  // The aim as a drag would set it: direction (any length) and the cue's speed in m/s.
  aim(direction, speed) {
    setAim(direction, speed);
    return prediction;
  },
  // The tip as the ball diagram would set it, in shares of the radius.
  setTip(side, height) {
    setTip(side, height);
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
drawTip();
setAim({x: 1, y: 0}, speedSlider.value);
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
