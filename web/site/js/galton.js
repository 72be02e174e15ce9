// "Galton board": balls poured into a hopper fall through rows of pegs under gravity and
// come to rest in the bins below; beside the board, the count in each bin over the binomial curve
// the geometry implies (galton_board.js). The falling, the bouncing (restitution 0.5) and the
// coming to rest, on the bins' floors and on each other, are carom's (carom::web::DrawnWorld over a
// carom::World with gravity); this page chooses where to pour, counts where balls have landed, and
// draws.
import {attempt, carom} from './carom.js';
import {packColour} from './disc_raster.js';
import {num} from './format.js';
import {BALL_RADIUS, MAX_BALLS, binOf, binomial, galtonBoard} from './galton_board.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const FRAME_TIME = 1 / 60;  // simulated time per frame
// In spacings per time unit²: a ball crosses the board in a few time units, slowly enough to
// follow by eye at 60 frames a second.
const GRAVITY = 30;
const RESTITUTION = 0.5;
const REST_HEIGHT = 1e-3;  // of a radius: carom's default, below anything the picture shows
// Should carom::World refuse a step (advance, below), every landed ball becomes an immovable ball
// at its place, this much smaller, so that it does not overlap its supports by the rounding of its
// resting place (carom refuses a ball added overlapping anything). docs/playground.md, "Galton
// board".
const FIXED_SHRINK = 1 - 1e-6;
// Balls leave the pour spout downwards at this speed, so that at a few dozen a second each has
// cleared the spot before the next is poured.
const POUR_SPEED = 6;
const STATS_KEPT = 3600;   // frames of timings kept (window.caromFrameStats): a minute

const PEG_COLOUR = packColour('#424242');
const FALLING_COLOUR = packColour('#1f6fb4');
// Landed balls alternate in colour from bin to bin, so that each bin's pile reads as one.
const LANDED_COLOURS = [packColour('#d62728'), packColour('#f28e2b')];
const SVG = 'http://www.w3.org/2000/svg';

const params = new URLSearchParams(location.search);
const board = galtonBoard();
const chances = binomial(board.rows);
const pegCount = board.pegs.length;
const painter = new WorldCanvas(document.getElementById('board'), {
  x: board.lower.x, y: board.lower.y, width: board.upper.x - board.lower.x,
  height: board.upper.y - board.lower.y});
const rate = slider('rate', () => {});
if (params.has('rate')) {
  rate.input.value = params.get('rate');
  rate.input.dispatchEvent(new Event('input'));
}
document.getElementById('rows').textContent = String(board.rows);

// A seeded generator (mulberry32), so that a page opened with the same ?seed pours the same balls
// in the same places: the pour is this page's input, and its runs repeat.
function generator(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
const random = generator(Number(params.get('seed') ?? 1));

let world = null;
let poured = 0;
let landed = 0;
// Per poured ball j, in the order poured: its index in the world (a new one once fixed), its bin
// once landed (else -1), and whether it has been fixed (after a refused step).
let ballIndex = [];
let landedBin = [];
let fixed = [];
let owner = [];      // per world index: the poured ball it is, or -1 (a peg, or a removed slot)
let stalled = false;  // the World refused a step even after fixing every landed ball
const counts = new Array(board.rows + 1).fill(0);
let due = 0;         // balls owed to the pour, carried from frame to frame
let pouring = params.get('pour') !== '0';
let frames = 0;
let histogramStale = true;
const stats = {step: [], draw: [], interval: []};
window.caromFrameStats = stats;
let lastFrameStart = null;

function keep(list, value) {
  list.push(value);
  if (list.length > STATS_KEPT) list.shift();
}

function build() {
  if (world) world.delete();
  world = new carom.DrawnWorld({
    boundary: carom.Boundary.box, lower: board.lower, upper: board.upper,
    restitution: RESTITUTION, collapse_time: 0, cell_size: 0,
    gravity: {x: 0, y: -GRAVITY}, rest_height: REST_HEIGHT});
  for (const s of board.segments) world.add_segment(s);
  for (const a of board.arcs) world.add_arc(a);
  // Immovable pegs: mass ∞ (carom::kImmovable); gravity does not move them.
  for (const p of board.pegs) world.add_ball(p, {x: 0, y: 0}, board.pegRadius, Infinity);
  poured = 0;
  landed = 0;
  ballIndex = [];
  landedBin = [];
  fixed = [];
  owner = new Array(pegCount).fill(-1);
  stalled = false;
  counts.fill(0);
  due = 0;
  histogramStale = true;
}

// ---- pouring and landing --------------------------------------------------------------------

function pour() {
  if (!pouring) return;
  due += rate.value * FRAME_TIME;
  while (due >= 1 && poured < MAX_BALLS) {
    const x = board.pour.x0 + random() * (board.pour.x1 - board.pour.x0);
    const y = board.pour.y + (random() - 0.5) * 0.2;
    let index;
    try {
      index = world.add_ball({x, y}, {x: (random() - 0.5) * 0.2, y: -POUR_SPEED}, BALL_RADIUS, 1);
    } catch {
      break;  // a ball is still where this one would go: pour it next frame
    }
    owner[index] = poured;
    ballIndex.push(index);
    landedBin.push(-1);
    fixed.push(false);
    ++poured;
    due -= 1;
  }
  // Balls owed while the pour spot was taken are not all poured at once afterwards.
  due = Math.min(due, 1);
  if (poured >= MAX_BALLS) setPouring(false);
}

// A ball has landed when it is below the bins' tops and too slow to climb back over them: its
// kinetic energy is less than the potential energy of the climb, so only another ball could lift
// it out, and a landed ball keeps its bin. balls: the world's snapshot (x, y, radius, speed).
function land(balls) {
  const top = board.bins.top - BALL_RADIUS;
  for (let j = 0; j < poured; ++j) {
    if (landedBin[j] >= 0) continue;
    const at = 4 * ballIndex[j];
    const climb = top - balls[at + 1];
    const speed = balls[at + 3];
    if (!(climb > 0 && speed * speed < 2 * GRAVITY * climb)) continue;
    const bin = binOf(board, balls[at]);
    landedBin[j] = bin;
    ++counts[bin];
    ++landed;
    histogramStale = true;
  }
}

// Replaces poured ball j by an immovable ball where it is (FIXED_SHRINK says why).
function fix(j) {
  const old = ballIndex[j];
  const p = world.position(old);
  world.remove_ball(old);
  owner[old] = -1;
  let index;
  try {
    index = world.add_ball(p, {x: 0, y: 0}, BALL_RADIUS * FIXED_SHRINK, Infinity);
  } catch {
    // Overlapping by more than the shrink: it stays a movable ball, at rest where it was.
    index = world.add_ball(p, {x: 0, y: 0}, BALL_RADIUS, 1);
  }
  owner[index] = j;
  ballIndex[j] = index;
  fixed[j] = true;
}

// One frame of carom::World::step. If the World refuses it (an inelastic collapse, or balls
// jammed: docs/world.md, "Known limits"; no pour measured refuses one, docs/playground.md), every
// landed ball is fixed where it is, slowing or not, and the rest of the frame is tried once more;
// a second refusal stops the board, with the World's message on the page.
function advance() {
  const start = world.time();
  try {
    world.step(FRAME_TIME);
    return;
  } catch {
    for (let j = 0; j < poured; ++j) if (landedBin[j] >= 0 && !fixed[j]) fix(j);
  }
  const left = Math.max(0, FRAME_TIME - (world.time() - start));
  if (attempt(() => world.step(left)) === undefined) {
    stalled = true;
    setPouring(false);
  }
}

// ---- drawing ------------------------------------------------------------------------------

function draw() {
  const balls = world.snapshot();
  painter.begin('#fafafa');
  for (let i = 0; i < balls.length; i += 4) {
    if (balls[i + 2] === 0) continue;  // a slot freed when its ball was fixed
    const j = owner[i / 4];
    let colour = PEG_COLOUR;
    if (j >= 0) colour = landedBin[j] >= 0 ? LANDED_COLOURS[landedBin[j] % 2] : FALLING_COLOUR;
    painter.disc(balls[i], balls[i + 1], balls[i + 2], colour);
  }
  painter.endDiscs();
  painter.segments(board.segments, '#333', 2);
  painter.arcs(board.arcs, '#424242', 2);
  painter.frame();
  return balls;
}

// The histogram: one bar per bin (data-bin, data-count), the binomial's expected counts as dots
// joined by a line, and a count axis that grows with the tallest of either.
const histogram = document.getElementById('histogram');
const PLOT = {left: 44, right: 392, top: 12, bottom: 228};

function element(name, attributes, text) {
  const node = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
  if (text !== undefined) node.textContent = text;
  return node;
}

// 1, 2, 5, 10, 20, 50, ...: the axis's top, at least value.
function niceCeil(value) {
  const power = 10 ** Math.floor(Math.log10(value));
  for (const step of [1, 2, 5, 10]) if (step * power >= value) return step * power;
  return 10 * power;
}

function drawHistogram() {
  const bins = board.rows + 1;
  const width = (PLOT.right - PLOT.left) / bins;
  const expected = chances.map((p) => p * landed);
  const top = niceCeil(Math.max(10, ...counts, ...expected));
  const y = (count) => PLOT.bottom - (PLOT.bottom - PLOT.top) * count / top;
  const x = (bin) => PLOT.left + (bin + 0.5) * width;
  const nodes = [];
  for (const tick of [0, top / 2, top]) {
    nodes.push(element('line', {class: 'tick', x1: PLOT.left, x2: PLOT.right, y1: y(tick),
                                y2: y(tick)}));
    nodes.push(element('text', {class: 'axis', x: PLOT.left - 6, y: y(tick) + 4,
                                'text-anchor': 'end'}, String(tick)));
  }
  counts.forEach((count, bin) => {
    nodes.push(element('rect', {class: `bar bin-${bin % 2}`, 'data-bin': bin, 'data-count': count,
                                x: x(bin) - 0.4 * width, width: 0.8 * width, y: y(count),
                                height: PLOT.bottom - y(count)}));
    nodes.push(element('text', {class: 'axis', x: x(bin), y: PLOT.bottom + 16,
                                'text-anchor': 'middle'}, String(bin)));
  });
  nodes.push(element('polyline', {class: 'binomial',
                                  points: expected.map((e, bin) => `${x(bin)},${y(e)}`).join(' ')}));
  expected.forEach((e, bin) => {
    nodes.push(element('circle', {class: 'binomial', 'data-bin': bin, 'data-expected': e,
                                  cx: x(bin), cy: y(e), r: 3}));
  });
  nodes.push(element('text', {class: 'axis', x: (PLOT.left + PLOT.right) / 2, y: 256,
                              'text-anchor': 'middle'}, 'bin (times the ball went right)'));
  histogram.replaceChildren(...nodes);
  histogramStale = false;
}

// ---- the readout ----------------------------------------------------------------------------

function report() {
  const mean = landed ? counts.reduce((s, c, bin) => s + c * bin, 0) / landed : NaN;
  const variance = landed
      ? counts.reduce((s, c, bin) => s + c * (bin - mean) ** 2, 0) / landed : NaN;
  const average = (list) => list.length
      ? num(list.slice(-60).reduce((s, v) => s + v, 0) / Math.min(60, list.length), 3)
      : undefined;
  fillReadout({
    poured: `${poured} of ${MAX_BALLS}`,
    landed: String(landed),
    falling: String(poured - landed),
    mean: landed ? `${num(mean, 4)} (binomial: ${num(board.rows / 2)})` : undefined,
    variance: landed ? `${num(variance, 4)} (binomial: ${num(board.rows / 4)})` : undefined,
    time: world.time().toFixed(2),
    collisions: String(world.collision_count()),
    kinetic: num(world.kinetic_energy(), 6),
    potential: num(world.potential_energy(), 6),
    step_ms: average(stats.step),
    draw_ms: average(stats.draw),
  });
}

// ---- running ----------------------------------------------------------------------------------

function frame(now) {
  if (lastFrameStart !== null) keep(stats.interval, now - lastFrameStart);
  lastFrameStart = now;
  if (!stalled) {
    pour();
    const start = performance.now();
    advance();
    land(world.snapshot());
    keep(stats.step, performance.now() - start);
  }
  const drawStart = performance.now();
  draw();
  keep(stats.draw, performance.now() - drawStart);
  // The histogram and the text change a few times a second, in the same frame, so that the
  // histogram's total and the count of landed balls always agree on the page.
  if (++frames % 6 === 0) {
    if (histogramStale) drawHistogram();
    report();
  }
  requestAnimationFrame(frame);
}

const pourButton = document.getElementById('pour');
function setPouring(on) {
  pouring = on && poured < MAX_BALLS && !stalled;
  pourButton.textContent = pouring ? 'Stop pouring' : 'Pour';
  pourButton.setAttribute('aria-pressed', String(pouring));
}
pourButton.addEventListener('click', () => setPouring(!pouring));
// Reset empties the board and keeps pouring or not as before; a board that was full pours again.
document.getElementById('reset').addEventListener('click', () => {
  const wasFull = poured >= MAX_BALLS;
  build();
  draw();
  drawHistogram();
  report();
  setPouring(pouring || wasFull);
});
window.addEventListener('resize', () => draw());

// For the tests (web/tests/galton.test.mjs): the world and what the page counted.
window.caromGalton = {
  get world() { return world; },
  board,
  pegCount,
  get poured() { return poured; },
  get landed() { return landed; },
  get landedBin() { return [...landedBin]; },
  get ballIndex() { return [...ballIndex]; },
  get fixed() { return fixed.filter((f) => f).length; },
  get stalled() { return stalled; },
  get counts() { return [...counts]; },
};

build();
setPouring(pouring);
draw();
drawHistogram();
report();
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
