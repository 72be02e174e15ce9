// "Many balls": a carom::World in a box, or any carom scene file (an example, or a file dropped on
// the page or chosen with the picker), advanced 1/60 time unit per frame and drawn on a canvas.
// The world, the dragging, the pockets and every number shown come from carom
// (carom::web::DrawnWorld; scene files through carom's scene library). Every scene is drawn y up,
// as carom's scene files and `carom render` draw them; an open world's view follows its balls.
import {attempt, carom} from './carom.js';
import {num, vec} from './format.js';
import {DiscRaster, packColour, packCssColour} from './disc_raster.js';
import {exampleSources, sceneFileSource, sceneSources} from './scene_sources.js';
import {fillReadout, slider} from './sliders.js';

const FRAME_TIME = 1 / 60;  // simulated time per frame
const COUNTS = [10, 30, 100, 300, 1000, 3000, 10000, 20000, 50000];
const RATE_WINDOW = 1;      // time units over which collisions per time unit are counted
const STATS_KEPT = 1200;    // frames of timings kept for the benchmark (web/bench)
const SPEED_COLOURS = ['#1e88e5', '#43a047', '#fdd835', '#fb8c00', '#e53935'];

const params = new URLSearchParams(location.search);
const canvas = document.getElementById('box');
const context = canvas.getContext('2d', {alpha: false});
const raster = new DiscRaster(context);
const BACKGROUND = packColour('#fafafa');
const BAND_COLOURS = SPEED_COLOURS.map(packColour);
const POCKET_COLOUR = packColour('#212121');
const RIM_COLOUR = packColour('#424242');
const RIM_WIDTH = 1;  // pixels
// Why a scene could not be loaded: the scene library's message (file:line:column: ...). Apart
// from the error line, which the next call that succeeds clears.
const sceneError = document.getElementById('scene-error');
// What "Check overlaps" found, for the world on the page.
const audit = document.getElementById('audit');
const speedLegend = document.getElementById('speed-legend');
const sources = [...sceneSources];
try {
  sources.push(...await exampleSources());
} catch (error) {
  sceneError.textContent = `The examples could not be listed: ${error.message}`;
}
const sceneSelect = document.getElementById('scene');
for (const source of sources) sceneSelect.add(new Option(source.label, source.id));
// ?scene=ID opens that source (e.g. example:billiards.json); an unknown ID is ignored.
if (sources.some((s) => s.id === params.get('scene'))) sceneSelect.value = params.get('scene');

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
  colourTop *= s / currentSpeed;
  currentSpeed = s;
  showSpeedLegend();
});
// carom::World fixes a ball's restitution when the ball is added, so a new e starts the scene
// again (re-adding the balls where they are could fail: after a contact two balls touch, and a
// rounding may count that as an overlap).
const restitution = slider('restitution', rebuild);

let world = null;
// Per ball: the colour the scene gives it, or 0 (coloured by speed, against colourTop).
let ballColours = new Uint32Array(0);
let colourTop = 1;
let pockets = [];
// The part of the world on the canvas, y up: the box (or periodic cell), or for an open world
// the extent of its balls, walls and pockets, refitted as the balls move (follow()).
let view = {x: 0, y: 0, width: 1, height: 1};
let open = false;
let walls = emptyExtent();  // an open world's segments, arcs and pockets
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

let rebuilds = 0;  // a slow load that a newer choice overtook is dropped

async function rebuild() {
  const source = sources.find((s) => s.id === sceneSelect.value);
  const ticket = ++rebuilds;
  for (const id of ['count', 'restitution']) document.getElementById(id).disabled = !!source.fromFile;
  if (source.load) {
    try {
      await source.load();
    } catch (error) {
      sceneError.textContent = `${source.label}: ${error.message}`;
      return;
    }
    if (ticket !== rebuilds) return;
  }
  install(source, loaded(() => source.build(carom, {
    count: COUNTS[Number(countInput.value)], speed: speed.value, restitution: restitution.value,
  })));
}

// build() made, or undefined with the reason shown on the page.
function loaded(build) {
  try {
    const built = build();
    sceneError.textContent = '';
    return built;
  } catch (error) {
    sceneError.textContent = String(error.message ?? error);
    return undefined;
  }
}

// Shows built (a DrawnWorld from source); nothing changes when the build failed (undefined: the
// error is on the page).
function install(source, built) {
  if (!built) return;
  if (world) world.delete();
  world = built;
  ballColours = Uint32Array.from(world.colors(), (text) => (text && packCssColour(text)) || 0);
  pockets = world.pockets();
  colourTop = source.fromFile ? 2 * meanSpeed(world) : 2 * speed.value;
  open = world.def().boundary === carom.Boundary.open;
  walls = open ? wallsOf(world) : emptyExtent();
  view = viewOf(world);
  canvas.style.aspectRatio = `${view.width} / ${view.height}`;
  currentSpeed = speed.value;
  audit.textContent = '';  // it spoke of the world just replaced
  showSpeedLegend();
  held = -1;
  history = [];
  for (const key of Object.keys(stats)) stats[key].length = 0;
  draw();
  report();
  document.body.dataset.scene = source.id;
}

function meanSpeed(w) {
  const balls = w.snapshot();
  let sum = 0;
  let moving = 0;
  for (let i = 0; i < balls.length; i += 4) {
    if (balls[i + 3] > 0) sum += balls[i + 3], ++moving;
  }
  return moving ? sum / moving : 1;
}

// The colours of balls drawn by speed, each band's range in the world's units: shown while any
// ball is drawn by speed (a scene that colours every ball needs none).
function showSpeedLegend() {
  speedLegend.hidden = !ballColours.some((colour) => colour === 0);
  const bands = SPEED_COLOURS.map((colour, i) => {
    const from = colourTop * i / SPEED_COLOURS.length;
    const last = i === SPEED_COLOURS.length - 1;
    const to = last ? Infinity : colourTop * (i + 1) / SPEED_COLOURS.length;
    const item = document.createElement('span');
    item.dataset.colour = colour;
    item.dataset.from = String(from);
    item.dataset.to = String(to);
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colour;
    item.append(swatch, last ? `${num(from, 3)} or more` : `${num(from, 3)} to ${num(to, 3)}`);
    return item;
  });
  speedLegend.replaceChildren('Speed, length units per time unit:', ...bands);
}

// ---- a scene file from the user ----------------------------------------------------------------

async function openFile(file) {
  const text = await file.text();
  const id = `file:${file.name}`;
  const source = sceneFileSource(id, `File: ${file.name}`, file.name, async () => text);
  await source.load();
  const built = loaded(() => source.build(carom));
  if (!built) return;  // the scene library's message (file:line:column) is on the page
  const old = sources.findIndex((s) => s.id === id);
  if (old >= 0) {
    sources[old] = source;
  } else {
    sources.push(source);
    sceneSelect.add(new Option(source.label, id));
  }
  sceneSelect.value = id;
  ++rebuilds;
  for (const name of ['count', 'restitution']) document.getElementById(name).disabled = true;
  install(source, built);
}

const fileInput = document.getElementById('scene-file');
fileInput.addEventListener('change', () => {
  if (fileInput.files.length) openFile(fileInput.files[0]);
  fileInput.value = '';
});
document.addEventListener('dragover', (event) => event.preventDefault());
document.addEventListener('drop', (event) => {
  event.preventDefault();
  const file = event.dataTransfer?.files[0];
  if (file) openFile(file);
});

// ---- drawing -------------------------------------------------------------------------------

const OPEN_MARGIN = 0.05;  // an open world's first view reaches this fraction beyond what it holds
// When an open world's balls leave the view (or gather in less than FOLLOW_SMALLEST of it both
// ways), the view refits around them with this much room, a share of the longer side, so that
// it does not have to move again at once.
const FOLLOW_MARGIN = 0.25;
const FOLLOW_SMALLEST = 0.3;

// An axis-aligned box in world units, empty until something is added (cover).
function emptyExtent() {
  return {x0: Infinity, y0: Infinity, x1: -Infinity, y1: -Infinity};
}

function cover(extent, x, y, r) {
  extent.x0 = Math.min(extent.x0, x - r);
  extent.y0 = Math.min(extent.y0, y - r);
  extent.x1 = Math.max(extent.x1, x + r);
  extent.y1 = Math.max(extent.y1, y + r);
}

function wallsOf(w) {
  const extent = emptyExtent();
  for (const s of w.segments()) cover(extent, s.a.x, s.a.y, 0), cover(extent, s.b.x, s.b.y, 0);
  for (const a of w.arcs()) cover(extent, a.center.x, a.center.y, a.radius);
  for (const p of w.pockets()) cover(extent, p.x, p.y, p.radius);
  return extent;
}

// The live balls (snapshot: x, y, radius, speed each; radius 0 once potted) and the walls.
function contentOf(balls) {
  const extent = {...walls};
  for (let i = 0; i < balls.length; i += 4) {
    if (balls[i + 2] > 0) cover(extent, balls[i], balls[i + 1], balls[i + 2]);
  }
  return extent;
}

function viewOf(w) {
  const def = w.def();
  if (def.boundary !== carom.Boundary.open) {
    return {x: def.lower.x, y: def.lower.y, width: def.upper.x - def.lower.x,
            height: def.upper.y - def.lower.y};
  }
  const extent = contentOf(w.snapshot());
  if (extent.x0 > extent.x1) return {x: -1, y: -1, width: 2, height: 2};
  const width = extent.x1 - extent.x0 || 1;
  const height = extent.y1 - extent.y0 || 1;
  return {x: extent.x0 - OPEN_MARGIN * width, y: extent.y0 - OPEN_MARGIN * height,
          width: width * (1 + 2 * OPEN_MARGIN), height: height * (1 + 2 * OPEN_MARGIN)};
}

// An open world's view follows its balls: refitted, in the canvas's proportions, when one
// leaves it or all gather in a small part of it. Returns whether it moved.
function follow(balls) {
  const e = contentOf(balls);
  if (e.x0 > e.x1) return false;
  const inside = e.x0 >= view.x && e.y0 >= view.y && e.x1 <= view.x + view.width &&
                 e.y1 <= view.y + view.height;
  const small = e.x1 - e.x0 < FOLLOW_SMALLEST * view.width &&
                e.y1 - e.y0 < FOLLOW_SMALLEST * view.height;
  if (inside && !small) return false;
  const margin = FOLLOW_MARGIN * Math.max(e.x1 - e.x0, e.y1 - e.y0, Number.MIN_VALUE);
  let width = e.x1 - e.x0 + 2 * margin;
  let height = e.y1 - e.y0 + 2 * margin;
  const aspect = view.width / view.height;
  if (width / height > aspect) height = width / aspect; else width = height * aspect;
  view = {x: (e.x0 + e.x1 - width) / 2, y: (e.y0 + e.y1 - height) / 2, width, height};
  return true;
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
  // x, y, radius, speed per ball (radius 0: potted), in the scene's colour or by speed.
  const balls = world.snapshot();
  if (open) follow(balls);
  resize();
  const scale = canvas.width / view.width;
  const px = (x) => (x - view.x) * scale;
  const py = (y) => (view.y + view.height - y) * scale;  // y up
  raster.begin(BACKGROUND);
  for (const p of pockets) raster.disc(px(p.x), py(p.y), p.radius * scale, POCKET_COLOUR);
  for (let i = 0; i < balls.length; i += 4) {
    if (balls[i + 2] === 0) continue;
    const band = Math.min(BAND_COLOURS.length - 1,
                          Math.floor(balls[i + 3] / colourTop * BAND_COLOURS.length));
    const colour = ballColours[i / 4];
    if (colour) {
      // A scene's own colour may be as light as the background (a white cue ball): a dark rim.
      raster.disc(px(balls[i]), py(balls[i + 1]), balls[i + 2] * scale, RIM_COLOUR);
      raster.disc(px(balls[i]), py(balls[i + 1]), balls[i + 2] * scale - RIM_WIDTH, colour);
    } else {
      raster.disc(px(balls[i]), py(balls[i + 1]), balls[i + 2] * scale, BAND_COLOURS[band]);
    }
  }
  raster.end();
  if (held >= 0 && balls[4 * held + 2] === 0) held = -1;  // it fell into a pocket
  // In pixels: a scene's length unit may be a metre or a millimetre.
  context.lineWidth = 2 * (window.devicePixelRatio || 1);
  context.strokeStyle = '#333';
  for (const s of world.segments()) {
    context.beginPath();
    context.moveTo(px(s.a.x), py(s.a.y));
    context.lineTo(px(s.b.x), py(s.b.y));
    context.stroke();
  }
  for (const a of world.arcs()) {
    context.beginPath();
    // y up: the world's angle θ is the screen's −θ, so the arc runs from −end to −start.
    context.arc(px(a.center.x), py(a.center.y), a.radius * scale, -a.end_angle, -a.start_angle);
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
    // Of gravity, in a scene file that sets it (0 otherwise): with the kinetic energy, the total
    // that elastic contacts keep.
    potential: num(world.potential_energy(), 10),
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
  audit.textContent =
      problem === undefined ? '' : problem || 'No two balls overlap; every ball is inside the box.';
});
sceneSelect.addEventListener('change', rebuild);

// ---- dragging --------------------------------------------------------------------------------

function worldPoint(event) {
  const box = canvas.getBoundingClientRect();
  return {x: view.x + (event.clientX - box.left) / box.width * view.width,
          y: view.y + view.height - (event.clientY - box.top) / box.height * view.height};
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

await rebuild();
setRunning(running);
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
