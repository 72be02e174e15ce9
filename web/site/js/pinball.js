// "Pinball": a table under gravity (pinball_table.js) with bumpers, slingshots and two flippers.
// The launch button (or the space bar) sends a ball up the plunger's lane; it comes down through
// the bumpers onto the flippers, which swing up while their key (or button) is held and down when
// it is let go, and leaves by the drain between them. The motion, the bounces and the energies
// are carom's (carom::web::DrawnWorld over a carom::World with gravity), and so are the flippers
// (moving walls: each swing a turn about the pivot for exactly the time to its stop, so a ball is
// hit at the exact instant with the flipper's own velocity there, and a flipper that stands still
// carries a ball resting on it), the drain (a sensor that removes the ball reaching it, at that
// instant) and the rollovers (sensors that report the balls passing, for the score); this page
// launches, flips, counts and draws.
import {attempt, carom} from './carom.js';
import {packColour} from './disc_raster.js';
import {num} from './format.js';
import {BALL_RADIUS, DRAIN_Y, FLIPPER_SWING, LANE_X, pinballTable} from './pinball_table.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const FRAME_TIME = 1 / 60;  // simulated time per frame: a time unit is a second
// A table tilted 6.5° gives a ball g·sin 6.5° ≈ 1.1 m/s² along it: 41 ball diameters a second².
const GRAVITY = 40;
const RESTITUTION = 0.8;  // the ball's, so every bounce (ball with bumper or wall) has it
const REST_HEIGHT = 1e-3;
const ENERGY_KEPT = 1200;  // frames of the energy log (for the tests)
// A flipper turns between its rest and its up angle (FLIPPER_SWING radians apart, the table's)
// at FLIPPER_SPEED radians a second: a swing takes 30 ms, its tip moving at about 90 diameters a
// second.
const FLIPPER_SPEED = 28;

const BALL_COLOUR = packColour('#9e9e9e');
const RIM_COLOUR = packColour('#424242');
const BUMPER_COLOUR = packColour('#1f6fb4');
const POST_COLOUR = packColour('#555555');

const table = pinballTable();
const painter = new WorldCanvas(document.getElementById('table'), {
  x: table.lower.x, y: table.lower.y, width: table.upper.x - table.lower.x,
  height: table.upper.y - table.lower.y});
const launchSpeed = slider('launch-speed', () => {});
const message = document.getElementById('message');

let world = null;
let fixedCount = 0;  // bumpers and posts: balls 0 .. fixedCount − 1
let inPlay = [];     // indices of the balls on the table
let launched = 0;
let drained = 0;
let score = 0;
let rolloverIds = [];  // the rollover sensors' wall ids
let flipperIds = [];   // the flippers' wall ids: left, right
let flips = 0;         // flipper swings started (a swing does work on the balls it hits)
const ROLLOVER_POINTS = 100;
let frames = 0;
// Per frame: the time, the total energy and the launches and drains so far. Between one launch
// or drain and the next the total can only fall (restitution < 1); the tests check it.
const energyLog = [];

function build() {
  if (world) world.delete();
  world = new carom.DrawnWorld({
    boundary: carom.Boundary.box, lower: table.lower, upper: table.upper,
    restitution: RESTITUTION, collapse_time: 0, cell_size: 0,
    gravity: {x: 0, y: -GRAVITY}, rest_height: REST_HEIGHT});
  for (const s of table.walls) world.add_segment(s);
  flipperIds = table.flippers.map((s) => world.add_segment(s));
  attempt(() => world.add_sensor_segment(table.drainLine, true));
  rolloverIds = table.rollovers.map((s) => attempt(() => world.add_sensor_segment(s, false)));
  // Immovable (mass ∞): gravity does not move them, and a ball cannot push them.
  for (const b of [...table.bumpers, ...table.posts]) {
    world.add_ball(b, {x: 0, y: 0}, b.radius, Infinity);
  }
  fixedCount = table.bumpers.length + table.posts.length;
  inPlay = [];
  launched = 0;
  drained = 0;
  score = 0;
  flips = 0;
  energyLog.length = 0;
}

// ---- the flippers -------------------------------------------------------------------------------

const angleOf = (s) => Math.atan2(s.b.y - s.a.y, s.b.x - s.a.x);

// Swings flipper `side` (0 left, 1 right) up or down from wherever it is: a turn about its pivot
// (its outer end) towards the up or the rest angle, lasting exactly until it gets there. The
// left flipper goes up counter-clockwise, the right one clockwise.
function swing(side, up) {
  const id = flipperIds[side];
  const now = world.wall_segment(id);
  const sign = side === 0 ? 1 : -1;
  let turned = sign * (angleOf(now) - angleOf(table.flippers[side]));
  turned -= 2 * Math.PI * Math.round(turned / (2 * Math.PI));
  const left = (up ? FLIPPER_SWING : 0) - turned;
  if (Math.abs(left) < 1e-9) return;
  attempt(() => world.set_wall_motion(id, {
    velocity: {x: 0, y: 0}, angular_velocity: sign * Math.sign(left) * FLIPPER_SPEED,
    pivot: now.a, duration: Math.abs(left) / FLIPPER_SPEED}));
  ++flips;
}

const flipperMoves = () => flipperIds.some((id) => world.wall_motion(id).duration > 0);

// A ball resting at the lane's foot is launched; otherwise a new ball is put there and launched,
// unless another ball is in the way.
function launch() {
  const up = {x: 0, y: launchSpeed.value};
  const balls = world.snapshot();
  for (const i of inPlay) {
    const [x, y, , speed] = balls.subarray(4 * i, 4 * i + 4);
    if (x > LANE_X && y < table.plunger.y + BALL_RADIUS && speed < 1) {
      attempt(() => world.set_velocity(i, up));
      ++launched;
      message.textContent = '';
      return;
    }
  }
  for (const i of inPlay) {
    const [x, y] = balls.subarray(4 * i, 4 * i + 2);
    if (Math.hypot(x - table.plunger.x, y - table.plunger.y) < 2 * BALL_RADIUS + 0.1) {
      message.textContent = 'A ball is in the lane: launch again once it has gone.';
      return;
    }
  }
  const index = attempt(() => world.add_ball(table.plunger, up, BALL_RADIUS, 1));
  if (index === undefined) return;
  inPlay.push(index);
  ++launched;
  message.textContent = '';
}

// The last step's sensor events: a ball the drain removed leaves play; a ball entering a
// rollover scores.
function count(events) {
  for (const e of events) {
    if (e.removed) {
      inPlay = inPlay.filter((i) => i !== e.ball);
      ++drained;
    } else if (e.enter && rolloverIds.includes(e.sensor)) {
      score += ROLLOVER_POINTS;
    }
  }
}

// ---- drawing -----------------------------------------------------------------------------

function draw() {
  const balls = world.snapshot();
  painter.begin('#f4f1e8');
  for (let i = 0; i < balls.length; i += 4) {
    if (balls[i + 2] === 0) continue;  // drained
    if (i / 4 < fixedCount) {
      const colour = i / 4 < table.bumpers.length ? BUMPER_COLOUR : POST_COLOUR;
      painter.disc(balls[i], balls[i + 1], balls[i + 2], colour);
    } else {
      // A silver ball with a dark rim, so that it shows on any part of the table.
      painter.disc(balls[i], balls[i + 1], balls[i + 2], RIM_COLOUR);
      painter.disc(balls[i], balls[i + 1], balls[i + 2] * 0.8, BALL_COLOUR);
    }
  }
  painter.endDiscs();
  painter.polygon(table.drain, '#212121');
  painter.label('drain', {x: LANE_X / 2, y: DRAIN_Y / 2}, '#fafafa');
  painter.segments(table.walls, '#333', 2);
  painter.segments(table.rollovers, '#2ca02c', 3);
  painter.segments(flipperIds.map((id) => world.wall_segment(id)), '#d62728', 6);
  painter.frame();
  return balls;
}

// ---- the readout ----------------------------------------------------------------------------

function report() {
  const kinetic = world.kinetic_energy();
  const potential = world.potential_energy();
  fillReadout({
    in_play: String(inPlay.length),
    launched: String(launched),
    drained: String(drained),
    score: String(score),
    time: world.time().toFixed(2),
    collisions: String(world.collision_count()),
    kinetic: num(kinetic, 6),
    potential: num(potential, 6),
    total: num(kinetic + potential, 6),
  });
}

// ---- running ----------------------------------------------------------------------------------

// One frame of table time: the step, the sensors, the picture and the energy log.
function advance() {
  // A flipper swinging during the step does work on the balls it hits.
  const swinging = flipperMoves();
  attempt(() => world.step(FRAME_TIME));
  count(world.sensor_events());
  draw();
  energyLog.push({time: world.time(), total: world.kinetic_energy() + world.potential_energy(),
                  launched, drained, flips, swinging});
  if (energyLog.length > ENERGY_KEPT) energyLog.shift();
  if (++frames % 6 === 0) report();
}

// Paused (by a test), the page keeps drawing nothing new: its frames come from advanceFrames.
let paused = false;

function frame() {
  if (!paused) advance();
  requestAnimationFrame(frame);
}

document.getElementById('launch').addEventListener('click', launch);
document.getElementById('reset').addEventListener('click', () => {
  build();
  draw();
  report();
});
// The space bar launches, except on a button or a control, where it already means something.
// The left flipper's keys are ArrowLeft and z, the right one's ArrowRight and /: held, it stays up.
const FLIPPER_KEYS = {ArrowLeft: 0, z: 0, Z: 0, ArrowRight: 1, '/': 1};
document.addEventListener('keydown', (event) => {
  if (event.repeat) return;
  if (event.key in FLIPPER_KEYS) {
    event.preventDefault();
    swing(FLIPPER_KEYS[event.key], true);
    return;
  }
  if (event.key !== ' ') return;
  if (event.target instanceof HTMLButtonElement || event.target instanceof HTMLInputElement) return;
  event.preventDefault();
  launch();
});
document.addEventListener('keyup', (event) => {
  if (!(event.key in FLIPPER_KEYS)) return;
  event.preventDefault();
  swing(FLIPPER_KEYS[event.key], false);
});
// A key let go while the page had no focus sends no keyup: leaving the page drops both flippers.
window.addEventListener('blur', () => {
  swing(0, false);
  swing(1, false);
});
// The on-screen flipper buttons, for touch: held down, the flipper stays up.
for (const [button, side] of [['flip-left', 0], ['flip-right', 1]]) {
  const element = document.getElementById(button);
  element.addEventListener('pointerdown', () => swing(side, true));
  for (const type of ['pointerup', 'pointerleave', 'pointercancel']) {
    element.addEventListener(type, () => swing(side, false));
  }
  // A long press on a phone would otherwise open a menu or select the button's text.
  element.addEventListener('contextmenu', (event) => event.preventDefault());
}
window.addEventListener('resize', () => draw());

// For the tests (web/tests/pinball.test.mjs).
window.caromPinball = {
  get world() { return world; },
  table,
  get inPlay() { return [...inPlay]; },
  get launched() { return launched; },
  get drained() { return drained; },
  get score() { return score; },
  get energyLog() { return [...energyLog]; },
  get flipperIds() { return [...flipperIds]; },
  flipperSwing: FLIPPER_SWING,
  // Stops the frame loop, so that a test counts table time in frames whatever the machine's load.
  pause() { paused = true; },
  resume() { paused = false; },
  // Runs n frames at once and returns ball i's position and velocity after each (paused only).
  advanceFrames(n, i) {
    const path = [];
    for (let k = 0; k < n; ++k) {
      advance();
      path.push(i === undefined ? null : {p: world.position(i), v: world.velocity(i)});
    }
    return path;
  },
  // A ball put in play at p, at rest (for the flipper test).
  dropBall(p) {
    const index = attempt(() => world.add_ball(p, {x: 0, y: 0}, BALL_RADIUS, 1));
    if (index !== undefined) inPlay.push(index);
    return index;
  },
};

build();
draw();
report();
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
