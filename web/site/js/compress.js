// "Compression": N disks at random in a periodic cell or a box grow at a common rate
// (Lubachevsky–Stillinger compression) until they jam, with a thermostat taking out the energy the
// growth pumps in. The start, the growth, the thermostat, the pressure, the contact network and
// ψ₆ are carom's (carom::web::make_packing and compress_frame over carom::science, the library
// `carom pack` uses); this page chooses the pace, decides when the packing counts as jammed,
// and draws.
import {attempt, carom} from './carom.js';
import {packColour} from './disc_raster.js';
import {num} from './format.js';
import {fillReadout, slider} from './sliders.js';
import {WorldCanvas} from './world_canvas.js';

const KT = 1;                // the thermostat's temperature, as carom pack's
const START_ETA = 0.3;       // carom pack's default start
const SIZED_FOR_ETA = 0.84;  // the first species' diameter is 1 near jamming, as in carom pack
const SECOND_DIAMETER = 1.4;
// Jammed once the reduced pressure passes this: lower than carom pack's 10¹², so that a few
// hundred disks jam in seconds in a browser; the gaps between touching disks are then about
// 10⁻⁸ of a diameter, far below a pixel.
const PRESSURE_LIMIT = 1e8;
const PRESSURE_LIMIT_TEXT = '10⁸';
// World time a frame covers (thermal speed 1: a disk moves a diameter in about half a second on
// the screen), and while compressing the time in which the diameters grow by GROWTH_PER_FRAME
// when that is longer, so that η climbs over a few hundred frames whatever the rate.
const FLUID_TIME = 1 / 30;
const GROWTH_PER_FRAME = 1e-3;
// The world's share of a frame: the collisions a frame may resolve follow the speed measured on
// this machine, so that frames near jamming, where time hardly moves on, stay smooth. A frame cut
// short leaves the rest of its time to the next (compress_frame's `until`), so the packing a
// start and a rate give does not hang on the machine.
const STEP_BUDGET_MS = 10;
const FIRST_COLLISIONS_PER_MS = 50;
const PRESSURE_SPAN_MS = 500;  // the pressure shown is measured over the frames of this span
const RATE_SPAN_MS = 1000;     // and the collisions per second over this one
const STATS_KEPT = 3600;       // frames of timings kept (window.caromFrameStats): a minute

// A disk's colour by its contacts, as `carom pack --picture` draws a packing
// (apps/carom/pack/packed_scene.cpp): rattlers grey, then 3, 4 (isostatic), 5, 6 and more.
const RATTLER_COLOUR = '#b0b0b0';
const CONTACT_COLOURS = ['#4c72b0', '#55a868', '#dd8452', '#c44e52'];
const PACKED_RATTLER = packColour(RATTLER_COLOUR);
const PACKED_CONTACTS = CONTACT_COLOURS.map(packColour);
const NETWORK_COLOUR = '#202020';

const params = new URLSearchParams(location.search);
const painter = new WorldCanvas(document.getElementById('cell'), {x: 0, y: 0, width: 1, height: 1});
const mixInput = document.getElementById('mix');
const boundaryInput = document.getElementById('boundary');
const rateInput = document.getElementById('rate');
const rateOut = document.getElementById('rate-out');
const compressButton = document.getElementById('compress');
const statusLine = document.getElementById('status');
const countInput = document.getElementById('count');
for (const [key, input] of [['n', countInput], ['mix', mixInput], ['boundary', boundaryInput]]) {
  if (params.has(key)) input.value = params.get(key);
}
const count = slider('count', () => build());
if (params.has('rate')) rateInput.value = String(Math.log10(Number(params.get('rate'))));
const seed = Number(params.get('seed') ?? 1);

let world = null;
let disks = 0;         // in the world
let periodic = true;
let compressing = false;
let jammed = null;     // once jammed: {pressure, stalled, eta}
let halted = false;    // the library refused a frame (its message is on the page) until New start
let network = null;    // carom's contact network of the world as drawn
let work = 0;          // the thermostat's, since the start
let until = 0;         // the world time the frames run to: FLUID_TIME or more beyond the last
let collisionsPerMs = FIRST_COLLISIONS_PER_MS;
let recent = [];       // per frame: {at, collisions, virial, time}
let frames = 0;
let reportDue = false;  // the readout is redrawn a few times a second, and at once on jamming
const stats = {step: [], draw: []};
window.caromFrameStats = stats;

function keep(list, value) {
  list.push(value);
  if (list.length > STATS_KEPT) list.shift();
}

// G, the smallest diameter's growth speed in thermal speeds: the slider is its log₁₀.
function growthRate() { return 10 ** Number(rateInput.value); }
function showRate() { rateOut.textContent = num(growthRate(), 2); }

// The cell's height over its width: for disks of one size, the cell a triangular crystal of the N
// fills exactly (rows of equal length, an even number of them so that their shift wraps round),
// the one nearest a square; otherwise a square.
function cellAspect(n, mono) {
  if (!mono) return 1;
  let best = 1;
  let bestMiss = Math.log(2);
  for (let rows = 2; rows <= n; rows += 2) {
    if (n % rows !== 0) continue;
    const aspect = rows * Math.sqrt(3) / 2 / (n / rows);
    const miss = Math.abs(Math.log(aspect));
    if (miss < bestMiss) {
      best = aspect;
      bestMiss = miss;
    }
  }
  return best;
}

function build() {
  if (world) world.delete();
  world = null;
  const mono = mixInput.value === 'mono';
  periodic = boundaryInput.value === 'periodic';
  const start = {
    count: count.value, second_diameter: mono ? 1 : SECOND_DIAMETER,
    second_fraction: mono ? 0 : 0.5,
    boundary: periodic ? carom.Boundary.periodic : carom.Boundary.box,
    aspect: cellAspect(count.value, mono), start_eta: START_ETA, sized_for_eta: SIZED_FOR_ETA,
    seed};
  world = attempt(() => carom.make_packing(start)) ?? null;
  disks = count.value;
  jammed = null;
  halted = false;
  setCompressing(false);
  work = 0;
  until = 0;
  recent = [];
  if (!world) return;
  const {lower, upper} = world.def();
  painter.setView({x: lower.x, y: lower.y, width: upper.x - lower.x, height: upper.y - lower.y});
  findNetwork();
}

// ---- running ------------------------------------------------------------------------------

// Z = PA/(NkT) over the frames of the last PRESSURE_SPAN_MS: 1 + Σ virial / (2·N·Σ time), as
// compress_frame measures one frame (docs/science.md, "Compression and jamming"); once jammed,
// that of the frame that jammed.
function pressure(now) {
  if (jammed) return jammed.pressure;
  let virial = 0;
  let time = 0;
  for (const f of recent) {
    if (now - f.at > PRESSURE_SPAN_MS) continue;
    virial += f.virial;
    time += f.time;
  }
  return time > 0 ? 1 + virial / (2 * disks * time) : undefined;
}

function collisionsPerSecond() {
  if (recent.length < 2) return undefined;
  const span = recent[recent.length - 1].at - recent[0].at;
  const total = recent.slice(1).reduce((s, f) => s + f.collisions, 0);
  return span > 0 ? total / span * 1000 : undefined;
}

function advance(now) {
  const rate = compressing ? growthRate() : 0;
  if (world.time() >= until) {
    until += compressing ? Math.max(FLUID_TIME, GROWTH_PER_FRAME / rate) : FLUID_TIME;
  }
  const budget = Math.max(disks, Math.round(collisionsPerMs * STEP_BUDGET_MS));
  const start = performance.now();
  const result = attempt(() => world.compress_frame({
    rate, kT: KT, until, collisions: budget, pressure_limit: compressing ? PRESSURE_LIMIT : 0}));
  const ms = performance.now() - start;
  keep(stats.step, ms);
  if (result === undefined) {
    halted = true;
    setCompressing(false);
    return;
  }
  // A frame of less than one window (N collisions) is mostly the call's own cost.
  if (result.collisions >= disks && ms > 0) {
    collisionsPerMs = 0.8 * collisionsPerMs + 0.2 * result.collisions / ms;
  }
  work += result.work;
  recent.push({at: now, collisions: result.collisions, virial: result.virial, time: result.time});
  const span = Math.max(PRESSURE_SPAN_MS, RATE_SPAN_MS);
  while (recent.length > 2 && now - recent[0].at > span) recent.shift();
  if (compressing && (result.over_pressure_limit || result.stalled)) {
    world.set_growth_rate(0);
    jammed = {pressure: result.window_pressure, stalled: result.stalled,
              eta: world.packing_fraction()};
    setCompressing(false);
    reportDue = true;
  }
}

// carom's contact network at the tolerance the pressure implies: gaps of about d/Z of a diameter
// between touching disks (science::contact_tolerance_at_pressure).
function findNetwork(now = performance.now()) {
  const z = pressure(now);
  network = world.contact_network(carom.contact_tolerance_at_pressure(z ?? 1));
}

// ---- drawing ------------------------------------------------------------------------------

function colourOf(i) {
  if (network.rattler[i]) return PACKED_RATTLER;
  return PACKED_CONTACTS[Math.max(0, Math.min(network.contacts[i], 6) - 3)];
}

function draw() {
  painter.begin('#fafafa');
  if (!world) {
    painter.frame();
    return;
  }
  const balls = world.snapshot();
  const {x: x0, y: y0, width, height} = painter.view;
  for (let i = 0; i < balls.length; i += 4) {
    const [x, y, r] = [balls[i], balls[i + 1], balls[i + 2]];
    const colour = colourOf(i / 4);
    // In a periodic cell a disk across a side shows on both sides.
    const xs = [x];
    const ys = [y];
    if (periodic) {
      if (x - r < x0) xs.push(x + width);
      if (x + r > x0 + width) xs.push(x - width);
      if (y - r < y0) ys.push(y + height);
      if (y + r > y0 + height) ys.push(y - height);
    }
    for (const u of xs) for (const v of ys) painter.disc(u, v, r, colour);
  }
  painter.endDiscs();
  // Each contact as two half-lines, one from each centre towards the other, so that a contact
  // across a periodic cell's side shows on both sides (as carom pack draws it).
  const lines = [];
  const pairs = network.pairs;
  for (let k = 0; k < pairs.length; k += 2) {
    const a = {x: balls[4 * pairs[k]], y: balls[4 * pairs[k] + 1]};
    const b = {x: balls[4 * pairs[k + 1]], y: balls[4 * pairs[k + 1] + 1]};
    let dx = b.x - a.x;
    let dy = b.y - a.y;
    if (periodic) {
      dx -= width * Math.round(dx / width);
      dy -= height * Math.round(dy / height);
    }
    lines.push({a, b: {x: a.x + dx / 2, y: a.y + dy / 2}});
    lines.push({a: b, b: {x: b.x - dx / 2, y: b.y - dy / 2}});
  }
  painter.segments(lines, NETWORK_COLOUR, 1);
  painter.frame();
}

function drawLegend() {
  const entries = [[RATTLER_COLOUR, 'rattler'], [CONTACT_COLOURS[0], '3 contacts'],
                   [CONTACT_COLOURS[1], '4 (isostatic)'], [CONTACT_COLOURS[2], '5'],
                   [CONTACT_COLOURS[3], '6 or more']];
  document.getElementById('contact-legend').replaceChildren(...entries.map(([colour, text]) => {
    const item = document.createElement('span');
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colour;
    item.append(swatch, text);
    return item;
  }));
}

// ---- the readout ----------------------------------------------------------------------------

function report(now) {
  if (!world) {
    fillReadout({});
    statusLine.textContent = '';
    return;
  }
  const z = pressure(now);
  const n = disks;
  const average = (list) => list.length
      ? num(list.slice(-60).reduce((s, v) => s + v, 0) / Math.min(60, list.length), 3)
      : undefined;
  const perSecond = jammed ? undefined : collisionsPerSecond();
  fillReadout({
    eta: num(world.packing_fraction(), 5),
    pressure: z === undefined ? undefined : num(z, 4),
    rate: perSecond === undefined ? undefined : num(perSecond, 3),
    collisions: String(world.collision_count()),
    time: num(world.time(), 6),
    work: num(work, 6),
    contacts: network.rattlers === n ? 'every disk a rattler'
        : `${num(network.mean_contacts_of_rest, 4)} (isostatic: 4)`,
    rattlers: `${network.rattlers} of ${n}`,
    pairs: String(network.pairs.length / 2),
    psi6: num(world.psi6(), 3),
    step_ms: average(stats.step),
    draw_ms: average(stats.draw),
  });
  if (jammed) {
    statusLine.textContent = jammed.stalled
        ? `Jammed at η = ${num(jammed.eta, 5)}: ${n} collisions no longer move time on.`
        : `Jammed at η = ${num(jammed.eta, 5)}: the pressure passed ${PRESSURE_LIMIT_TEXT}.`;
  } else {
    statusLine.textContent = compressing ? `Compressing at G = ${num(growthRate(), 2)}.`
        : 'A gas at fixed size: Compress makes the disks grow.';
  }
  statusLine.dataset.state = jammed ? 'jammed' : compressing ? 'compressing' : 'gas';
}

function frame(now) {
  if (world && !jammed && !halted) {
    advance(now);
    findNetwork(now);
  }
  const drawStart = performance.now();
  draw();
  keep(stats.draw, performance.now() - drawStart);
  if (++frames % 6 === 0 || reportDue) {
    report(now);
    reportDue = false;
  }
  requestAnimationFrame(frame);
}

function setCompressing(on) {
  compressing = on && world !== null && !jammed;
  compressButton.textContent = jammed ? 'Jammed' : compressing ? 'Stop compressing' : 'Compress';
  compressButton.disabled = jammed !== null || world === null;
  compressButton.setAttribute('aria-pressed', String(compressing));
}

compressButton.addEventListener('click', () => setCompressing(!compressing));
document.getElementById('reset').addEventListener('click', () => {
  build();
  draw();
  report(performance.now());
});
mixInput.addEventListener('change', () => build());
boundaryInput.addEventListener('change', () => build());
rateInput.addEventListener('input', showRate);
window.addEventListener('resize', () => draw());

// For the tests (web/tests/compress.test.mjs): the world and what the page decided.
window.caromCompression = {
  get world() { return world; },
  get compressing() { return compressing; },
  get jammed() { return jammed; },
  get network() { return network; },
  get work() { return work; },
};

showRate();
drawLegend();
build();
setCompressing(params.get('compress') === '1');
draw();
report(performance.now());
requestAnimationFrame(frame);
document.body.dataset.ready = 'true';
