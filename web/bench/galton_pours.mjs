// Whole pours of the "Galton board" page (not a test): each RATE:SEED pours its 1000 balls at RATE
// a second from seed SEED, in a headless chromium of its own (all pours at once), and is watched
// until every ball has landed and stands still, a step is refused twice (the board stalls), or
// --max-time simulated time units have passed. For each: the steps carom refused (and the first
// message), the balls landed and held, when all stood still, the collisions, the World's audit,
// the fullest bin and the highest pile, the spread, and step plus drawing over every frame.
//
//   node web/bench/galton_pours.mjs [--json] [--max-time T] [RATE:SEED ...]
//                                   (default: 40:1 20:2 10:3 5:1, T 400)
//
// The page advances 1/60 time unit a frame whatever the machine does, so a pour's course is the
// same on every run; only the frame times and the wall time depend on the machine (and on the
// other pours beside it: give one RATE:SEED alone for its frame times). Times are read every half
// second of wall time, so "at rest by" is late by up to about half a time unit.
import {cpus, loadavg} from 'node:os';

import {openBrowser, openPage} from '../tests/browser.mjs';

const args = process.argv.slice(2);
const json = args.includes('--json');
const maxAt = args.indexOf('--max-time');
const maxTime = maxAt >= 0 ? Number(args[maxAt + 1]) : 400;
const pours = args.filter((a) => /^\d+:\d+$/.test(a)).map((a) => a.split(':').map(Number));
if (pours.length === 0) pours.push([40, 1], [20, 2], [10, 3], [5, 1]);
const POLL_MS = 500;
const FRAME_BUDGET_MS = 1000 / 60;

function summary(list) {
  const sorted = [...list].sort((a, b) => a - b);
  const at = (q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  return {frames: sorted.length, median: at(0.5), p99: at(0.99), max: sorted[sorted.length - 1],
          over_budget: sorted.filter((v) => v > FRAME_BUDGET_MS).length};
}

// The page's state, read in one go: its counts, how many balls move, and the frame times since
// the last look (taken out of window.caromFrameStats, which keeps only the last minute).
function look(page) {
  return page.evaluate(() => {
    const g = window.caromGalton;
    const w = g.world;
    const stats = window.caromFrameStats;
    const work = stats.step.map((s, i) => s + (stats.draw[i] ?? 0));
    for (const list of Object.values(stats)) list.length = 0;
    const moving = g.ballIndex.filter((i) => {
      const v = w.velocity(i);
      return v.x !== 0 || v.y !== 0;
    }).length;
    return {poured: g.poured, landed: g.landed, held: g.fixed, stalled: g.stalled,
            time: w.time(), moving, collisions: w.collision_count(),
            refusals: window.caromRefusals, work};
  });
}

async function pour([rate, seed]) {
  const session = await openBrowser();
  try {
    // The pour starts with the page (t = 0), so that it runs the same every time; a ball poured
    // a fraction of a frame later takes another path down the pegs.
    const {page, problems} = await openPage(session, `galton.html?rate=${rate}&seed=${seed}`);
    // Every step carom refuses, recorded before the page's own fallback handles it (the first
    // balls are still falling when this is in place).
    await page.evaluate(() => {
      window.caromRefusals = [];
      const w = window.caromGalton.world;
      const step = w.step.bind(w);
      w.step = (dt) => {
        try {
          return step(dt);
        } catch (error) {
          window.caromRefusals.push({time: w.time(), message: String(error.message ?? error)});
          throw error;
        }
      };
    });
    const work = [];
    let s;
    let restAt = null;
    for (;;) {
      await page.waitForTimeout(POLL_MS);
      s = await look(page);
      work.push(...s.work);
      if (s.poured === s.landed && s.landed > 0 && s.moving === 0 && s.poured >= 1000) {
        restAt = s.time;
      }
      if (restAt !== null || s.stalled || s.time > maxTime) break;
    }
    const end = await page.evaluate(() => {
      const g = window.caromGalton;
      const floor = g.board.lower.y;
      const pile = new Array(g.counts.length).fill(0);
      g.ballIndex.forEach((i, j) => {
        const bin = g.landedBin[j];
        const height = g.world.position(i).y + g.board.ballRadius - floor;
        if (bin >= 0) pile[bin] = Math.max(pile[bin], height);
      });
      return {audit: g.world.audit(), kinetic: g.world.kinetic_energy(), counts: g.counts, pile,
              error: document.getElementById('error-line').textContent};
    });
    const landed = end.counts.reduce((sum, c) => sum + c, 0);
    const mean = end.counts.reduce((sum, c, bin) => sum + c * bin, 0) / landed;
    const variance = end.counts.reduce((sum, c, bin) => sum + c * (bin - mean) ** 2, 0) / landed;
    await page.close();
    return {rate, seed, refused: s.refusals.length, first_refusal: s.refusals[0] ?? null,
            stalled: s.stalled, error_line: end.error, poured: s.poured, landed: s.landed,
            held: s.held, moving: s.moving, at_rest_by: restAt, time: s.time,
            collisions: s.collisions, kinetic_energy: end.kinetic, audit: end.audit,
            counts: end.counts, fullest_bin: Math.max(...end.counts),
            highest_pile: Math.max(...end.pile), variance,
            step_plus_draw_ms: summary(work), console_errors: problems};
  } finally {
    await session.close();
  }
}

const results = await Promise.all(pours.map(pour));
const machine = {cpus: cpus().length, cpu: cpus()[0]?.model, load_average: loadavg()};
if (json) {
  console.log(JSON.stringify({machine, results}, null, 2));
} else {
  const f = (v, digits = 1) => v.toFixed(digits);
  console.log(`${machine.cpus} × ${machine.cpu}, load average ` +
              machine.load_average.map((v) => v.toFixed(2)).join(' '));
  for (const r of results) {
    const rest = r.at_rest_by !== null ? `all at rest by t = ${f(r.at_rest_by)}`
                                       : `${r.moving} still moving at t = ${f(r.time)}`;
    console.log(`\nrate ${r.rate}, seed ${r.seed}: ${r.refused} steps refused` +
                (r.stalled ? ' (stalled)' : '') + `, ${r.landed} of ${r.poured} landed, ` +
                `${r.held} held, ${rest}, ${r.collisions} collisions, kinetic energy ` +
                `${r.kinetic_energy}, audit ${r.audit === '' ? 'clean' : r.audit}`);
    if (r.first_refusal) {
      console.log(`  first refused at t = ${r.first_refusal.time}: ${r.first_refusal.message}`);
    }
    console.log(`  bins ${r.counts.join(' ')}; fullest ${r.fullest_bin}, highest pile ` +
                `${f(r.highest_pile, 2)}, variance ${f(r.variance, 2)}`);
    const w = r.step_plus_draw_ms;
    console.log(`  step + draw over ${w.frames} frames: median ${f(w.median)} ms, ` +
                `p99 ${f(w.p99)} ms, max ${f(w.max)} ms, ${w.over_budget} over 1/60 s`);
    if (r.console_errors.length) console.log('  console errors:', r.console_errors);
  }
}
