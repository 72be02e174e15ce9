// The frame-time benchmark of the "Many balls" page (not a test): N balls in headless chromium,
// the page's own timings of each frame (window.caromFrameStats: the world's step, the drawing,
// and the interval between animation frames), summarised. `galton` in place of an N measures the
// "Galton board" page instead, pouring 40 balls a second from the start.
//
//   node web/bench/frame_times.mjs [--json] [--seconds S] [N | galton ...]   (default N: 10000)
//
// The page advances 1/60 time unit per animation frame; the browser asks for a frame every
// 1/60 s when the previous one is done in time, so intervals near 16.7 ms mean 60 frames a second.
import {cpus, loadavg} from 'node:os';

import {openBrowser, openPage, readout} from '../tests/browser.mjs';

const args = process.argv.slice(2);
const json = args.includes('--json');
const secondsAt = args.indexOf('--seconds');
const seconds = secondsAt >= 0 ? Number(args[secondsAt + 1]) : 10;
const counts = args.filter((a, i) => (/^\d+$/.test(a) || a === 'galton') &&
                                     (secondsAt < 0 || i !== secondsAt + 1))
                   .map((a) => (a === 'galton' ? a : Number(a)));
if (counts.length === 0) counts.push(10000);
const GALTON = 'galton.html?rate=40';
const WARM_UP_MS = 2000;  // the lattice start melts and the JIT settles before timing
const FRAME_BUDGET_MS = 1000 / 60;

function summary(list) {
  const sorted = [...list].sort((a, b) => a - b);
  const at = (q) => sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
  const mean = sorted.reduce((s, v) => s + v, 0) / sorted.length;
  return {frames: sorted.length, mean, median: at(0.5), p95: at(0.95), p99: at(0.99),
          max: sorted[sorted.length - 1]};
}

const session = await openBrowser();
const results = [];
try {
  for (const n of counts) {
    const galton = n === 'galton';
    const {page, problems} = await openPage(session, galton ? GALTON : `many-balls.html?n=${n}`);
    await page.waitForTimeout(WARM_UP_MS);
    const t0 = Number(await readout(page, 'time'));
    const c0 = Number(await readout(page, 'collisions'));
    await page.evaluate(() => {
      for (const list of Object.values(window.caromFrameStats)) list.length = 0;
    });
    await page.waitForTimeout(seconds * 1000);
    const stats = await page.evaluate(() => window.caromFrameStats);
    const t1 = Number(await readout(page, 'time'));
    const c1 = Number(await readout(page, 'collisions'));
    const work = stats.step.map((s, i) => s + (stats.draw[i] ?? 0));
    results.push({
      // The Galton board's balls at the end of the run (poured, of its 1000).
      balls: galton ? `${await readout(page, 'poured')} on the Galton board`
                    : Number(await readout(page, 'balls')),
      wall_seconds: seconds,
      simulated_time: t1 - t0,
      frames_per_second: stats.interval.length / seconds,
      collisions_per_frame: (c1 - c0) / Math.max(1, Math.round((t1 - t0) * 60)),
      on_time_fraction: stats.interval.filter((v) => v <= FRAME_BUDGET_MS * 1.2).length /
                        stats.interval.length,
      interval_ms: summary(stats.interval),
      step_ms: summary(stats.step),
      draw_ms: summary(stats.draw),
      step_plus_draw_ms: summary(work),
      console_errors: problems,
    });
    await page.close();
  }
} finally {
  await session.close();
}

const machine = {cpus: cpus().length, cpu: cpus()[0]?.model, load_average: loadavg(),
                 chromium: session.browser.version()};
if (json) {
  console.log(JSON.stringify({machine, results}, null, 2));
} else {
  const f = (v) => v.toFixed(2);
  console.log(`chromium ${machine.chromium}, ${machine.cpus} × ${machine.cpu}, load average ` +
              machine.load_average.map((v) => v.toFixed(2)).join(' '));
  for (const r of results) {
    console.log(`\nN = ${r.balls}: ${r.frames_per_second.toFixed(1)} frames/s over ${seconds} s, ` +
                `${(100 * r.on_time_fraction).toFixed(1)} % of frame intervals within 1.2 × 16.7 ms, ` +
                `${r.collisions_per_frame.toFixed(0)} collisions per frame`);
    console.log('               mean  median    p95    p99    max   (ms)');
    for (const key of ['interval_ms', 'step_ms', 'draw_ms', 'step_plus_draw_ms']) {
      const s = r[key];
      console.log(`${key.padEnd(18)} ${f(s.mean).padStart(6)} ${f(s.median).padStart(6)} ` +
                  `${f(s.p95).padStart(6)} ${f(s.p99).padStart(6)} ${f(s.max).padStart(6)}`);
    }
    if (r.console_errors.length) console.log('console errors:', r.console_errors);
  }
}
