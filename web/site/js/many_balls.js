// "Many balls": a carom::World in a box, advanced 1/60 time unit per frame and drawn on a canvas.
// The world, the dragging and every number shown come from carom (carom::web::DrawnWorld).
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {DiscRaster, packColour} from './disc_raster.js';
import {sceneSources} from './scene_sources.js';
import {fillReadout, slider} from './sliders.js';

const FRAME_TIME = 1 / 60;  // simulated time per frame
const COUNTS = [10, 30, 100, 300, 1000, 3000, 10000, 20000, 50000];
const RATE_WINDOW = 1;      // time units over which collisions per time unit are counted
const STATS_KEPT = 1200;    // frames of timings kept for the benchmark (web/bench)
const SPEED_COLOURS = ['#1e88e5', '#43a047', '#fdd835', '#fb8c00', '#e53935'];

const canvas = document.getElementById('box');
const context = canvas.getContext('2d', {alpha: false});
const raster = new DiscRaster(context);
const BACKGROUND = packColour('#fafafa');
const BAND_COLOURS = SPEED_COLOURS.map(packColour);
const sceneSelect = document.getElementById('scene');
for (const source of sceneSources) sceneSelect.add(new Option(source.label, source.id));

const params = new URLSearchParams(location.search);
const countInput = document.getElementById('count');
if (params.has('n')) {
  const wanted = Number(params.get('n'));
  const index = COUNTS.findIndex((c) => c >= wanted);
  countInput.value = String(index < 0 ? COUNTS.length - 1 : index);
}
const countOut = document.getElementById('count-out');
const showCount = () => { countOut.textContent = String(COUNTS[Number(countInput.value)]); };
slider('count', () => { showCount(); rebuild(); });
showCount();
let currentSpeed = Number(document.getElementById('speed').value);
const speed = slider('speed', (s) => {
  attempt(() => world.scale_speeds(s / currentSpeed));
  currentSpeed = s;
});
// carom::World fixes a ball's restitution when the ball is added, so a new e starts the scene
// again (re-adding the balls where they are could fail: after a contact two balls touch, and a
// rounding may count that as an overlap).
const restitution = slider('restitution', rebuild);

let world = null;
// The part of the world on the canvas: the box (or periodic cell), or for an open world the
// extent of its balls and walls when it was built.
let view = {x: 0, y: 0, width: 1, height: 1};
let running = params.get('paused') !== '1';
let held = -1;
let history = [];  // [time, collision count] per frame, for the rate
let frames = 0;
let lastFrameStart = null;
// Timings of recent frames, in milliseconds: the step, the drawing, and the interval between
// frames as the browser schedules them. Read by web/bench/frame_times.mjs.
const stats = {step: [], draw: [], interval: []};
window.caromFrameStats = stats;

function keep(list, value) {
  list.push(value);
  if (list.length > STATS_KEPT) list.shift();
}

function rebuild() {
  const source = sceneSources.find((s) => s.id === sceneSelect.value);
  const built = attempt(() => source.build(carom, {
    count: COUNTS[Number(countInput.value)], speed: speed.value, restitution: restitution.value,
  }));
  if (!built) return;
  if (world) world.delete();
  world = built;
  view = viewOf(world);
  canvas.style.aspectRatio = `${view.width} / ${view.height}`;
  currentSpeed = speed.value;
  held = -1;
  history = [];
  for (const key of Object.keys(stats)) stats[key].length = 0;
  draw();
  report();
}

// ---- drawing -------------------------------------------------------------------------------

const OPEN_MARGIN = 0.05;  // an open world's view reaches this fraction beyond what it holds

function viewOf(w) {
  const def = w.def();
  if (def.boundary !== carom.Boundary.open) {
    return {x: def.lower.x, y: def.lower.y, width: def.upper.x - def.lower.x,
            height: def.upper.y - def.lower.y};
  }
  const extent = {x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity};
  const cover = (x, y, r) => {
    extent.x0 = Math.min(extent.x0, x - r);
    extent.y0 = Math.min(extent.y0, y - r);
    extent.x1 = Math.max(extent.x1, x + r);
    extent.y1 = Math.max(extent.y1, y + r);
  };
  const balls = w.snapshot();
  for (let i = 0; i < balls.length; i += 4) cover(balls[i], balls[i + 1], balls[i + 2]);
  for (const s of w.segments()) cover(s.a.x, s.a.y, 0), cover(s.b.x, s.b.y, 0);
  for (const a of w.arcs()) cover(a.center.x, a.center.y, a.radius);
  if (extent.x0 > extent.x1) return {x: -1, y: -1, width: 2, height: 2};
  const width = extent.x1 - extent.x0 || 1;
  const height = extent.y1 - extent.y0 || 1;
  return {x: extent.x0 - OPEN_MARGIN * width, y: extent.y0 - OPEN_MARGIN * height,
          width: width * (1 + 2 * OPEN_MARGIN), height: height * (1 + 2 * OPEN_MARGIN)};
}

function resize() {
  const ratio = window.devicePixelRatio || 1;
  const width = Math.round(canvas.clientWidth * ratio);
  const height = Math.round(width * view.height / view.width);
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
}

function draw() {
  resize();
  const scale = canvas.width / view.width;
  const px = (x) => (x - view.x) * scale;
  const py = (y) => (y - view.y) * scale;
  // x, y, radius, speed per ball, coloured by speed.
  const balls = world.snapshot();
  const top = 2 * currentSpeed;
  raster.begin(BACKGROUND);
  for (let i = 0; i < balls.length; i += 4) {
    const band = Math.min(BAND_COLOURS.length - 1,
                          Math.floor(balls[i + 3] / top * BAND_COLOURS.length));
    raster.disc(px(balls[i]), py(balls[i + 1]), balls[i + 2] * scale, BAND_COLOURS[band]);
  }
  raster.end();
  context.lineWidth = Math.max(1, scale * 0.15);
  context.strokeStyle = '#333';
  for (const s of world.segments()) {
    context.beginPath();
    context.moveTo(px(s.a.x), py(s.a.y));
    context.lineTo(px(s.b.x), py(s.b.y));
    context.stroke();
  }
  for (const a of world.arcs()) {
    context.beginPath();
    context.arc(px(a.center.x), py(a.center.y), a.radius * scale, a.start_angle,
                a.end_angle);
    context.stroke();
  }
  if (held >= 0) {
    const p = world.position(held);
    context.beginPath();
    context.arc(px(p.x), py(p.y), balls[4 * held + 2] * scale + 2, 0, 2 * Math.PI);
    context.strokeStyle = '#000';
    context.lineWidth = 2;
    context.stroke();
  }
  context.strokeStyle = '#333';
  context.lineWidth = 2;
  context.strokeRect(1, 1, canvas.width - 2, canvas.height - 2);
}

// ---- the readout -----------------------------------------------------------------------------

function report() {
  const time = world.time();
  const count = world.collision_count();
  history.push([time, count]);
  while (history.length > 2 && history[1][0] <= time - RATE_WINDOW) history.shift();
  const [then, countThen] = history[0];
  // Blank (a dash) until a frame has been timed.
  const mean = (list) => list.length ? num(list.reduce((s, v) => s + v, 0) / list.length, 3)
                                     : undefined;
  const recent = (list) => list.slice(-60);
  fillReadout({
    balls: String(world.ball_count()),
    time: time.toFixed(3),
    collisions: String(count),
    rate: time > then ? num((count - countThen) / (time - then), 4) : '—',
    // Ten digits: for e = 1 the energy is conserved to rounding (about 10⁻¹³ relative), so
    // every digit shown must stay put.
    energy: num(world.kinetic_energy(), 10),
    momentum: vec(world.momentum(), 4),
    step_ms: mean(recent(stats.step)),
    draw_ms: mean(recent(stats.draw)),
    frame_ms: mean(recent(stats.interval)),
  });
}

// ---- running -----------------------------------------------------------------------------

function advance() {
  const start = performance.now();
  attempt(() => world.step(FRAME_TIME));
  keep(stats.step, performance.now() - start);
}

function frame(now) {
  if (lastFrameStart !== null && running) keep(stats.interval, now - lastFrameStart);
  lastFrameStart = now;
  if (running && world) {
    advance();
    const start = performance.now();
    draw();
    keep(stats.draw, performance.now() - start);
    // The text changes a few times a second: often enough to read, rarely enough to cost nothing.
    if (++frames % 6 === 0) report();
  }
  requestAnimationFrame(frame);
}

const pauseButton = document.getElementById('pause');
function setRunning(on) {
  running = on;
  pauseButton.textContent = on ? 'Pause' : 'Run';
  if (!on) report();
}
pauseButton.addEventListener('click', () => setRunning(!running));
document.getElementById('step').addEventListener('click', () => {
  setRunning(false);
  advance();
  draw();
  report();
});
document.getElementById('reset').addEventListener('click', rebuild);
// carom::World::audit: a brute-force look at every pair (slow for 10⁴ balls, hence a button).
document.getElementById('check').addEventListener('click', () => {
  const problem = attempt(() => world.audit());
  document.getElementById('audit').textContent =
      problem === undefined ? '' : problem || 'No two balls overlap; every ball is inside the box.';
});
sceneSelect.addEventListener('change', rebuild);

// ---- dragging --------------------------------------------------------------------------------

function worldPoint(event) {
  const box = canvas.getBoundingClientRect();
  return {x: view.x + (event.clientX - box.left) / box.width * view.width,
          y: view.y + (event.clientY - box.top) / box.height * view.height};
}

canvas.addEventListener('pointerdown', (event) => {
  const index = attempt(() => world.ball_at(worldPoint(event)));
  if (index === undefined || index < 0) return;
  event.preventDefault();
  canvas.setPointerCapture(event.pointerId);
  held = index;
  attempt(() => world.hold(held));
  draw();
});
canvas.addEventListener('pointermove', (event) => {
  if (held < 0) return;
  attempt(() => world.drag_to(held, worldPoint(event)));
  if (!running) draw();
});
const letGo = () => {
  if (held < 0) return;
  attempt(() => world.release(held));
  held = -1;
  if (!running) draw();
};
canvas.addEventListener('pointerup', letGo);
canvas.addEventListener('pointercancel', letGo);
window.addEventListener('resize', () => { if (world) draw(); });

// For the tests (web/tests): the world, to find where a ball is before dragging it.
window.caromPlayground = {get world() { return world; }, get view() { return view; }};

rebuild();
setRunning(running);
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
