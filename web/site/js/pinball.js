// "Pinball": a table under gravity (pinball_table.js) with bumpers, slingshots and two flippers
// that do not move. The launch button (or the space bar) sends a ball up the plunger's lane;
// it comes down through the bumpers and leaves by the drain between the flippers. The motion,
// the bounces and the energies are carom's (carom::web::DrawnWorld over a carom::World with
// gravity), and so are the drain (a sensor that removes the ball reaching it, at that instant)
// and the rollovers (sensors that report the balls passing, for the score); this page launches,
// counts and draws.
import {attempt, carom} from './carom.js';
import {packColour} from './disc_raster.js';
import {num} from './format.js';
import {BALL_RADIUS, DRAIN_Y, LANE_X, pinballTable} from './pinball_table.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const FRAME_TIME = 1 / 60;  // simulated time per frame: a time unit is a second
// A table tilted 6.5° gives a ball g·sin 6.5° ≈ 1.1 m/s² along it: 41 ball diameters a second².
const GRAVITY = 40;
const RESTITUTION = 0.8;  // the ball's, so every bounce (ball with bumper or wall) has it
const REST_HEIGHT = 1e-3;
const ENERGY_KEPT = 1200;  // frames of the energy log (for the tests)

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
  for (const s of [...table.walls, ...table.flippers]) world.add_segment(s);
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
  energyLog.length = 0;
}

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
  painter.segments(table.flippers, '#d62728', 6);
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

function frame() {
  attempt(() => world.step(FRAME_TIME));
  count(world.sensor_events());
  draw();
  energyLog.push({time: world.time(), total: world.kinetic_energy() + world.potential_energy(),
                  launched, drained});
  if (energyLog.length > ENERGY_KEPT) energyLog.shift();
  if (++frames % 6 === 0) report();
  requestAnimationFrame(frame);
}

document.getElementById('launch').addEventListener('click', launch);
document.getElementById('reset').addEventListener('click', () => {
  build();
  draw();
  report();
});
// The space bar launches, except on a button or a control, where it already means something.
document.addEventListener('keydown', (event) => {
  if (event.key !== ' ' || event.repeat) return;
  if (event.target instanceof HTMLButtonElement || event.target instanceof HTMLInputElement) return;
  event.preventDefault();
  launch();
});
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
};

build();
draw();
report();
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
