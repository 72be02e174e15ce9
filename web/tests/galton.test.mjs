// "Galton board": balls poured for a few seconds land in the bins; the histogram beside the board
// counts exactly the balls landed and draws the binomial curve scaled to them; every landed ball
// lies in the bin it was counted in and every ball stays in the box; landed balls stay carom's
// movable balls, some of them at rest under carom's resting contact; the pour stops and
// starts, and Reset empties the board.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, expectReadout, openBrowser, openPage, readout} from './browser.mjs';

// At 60 frames a second the first balls land after about 3 s; a loaded machine gives fewer frames.
const RUN_TIMEOUT_MS = 120000;
const LANDED_WANTED = 40;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

// What the page shows and what it counted, read in one go (between two frames).
function state(page) {
  return page.evaluate(() => {
    const g = window.caromGalton;
    const number = (key) => document.querySelector(`[data-readout="${key}"]`).textContent;
    const balls = g.ballIndex.map((i) => g.world.position(i));
    const resting = g.ballIndex.filter((i, j) => {
      const v = g.world.velocity(i);
      return g.landedBin[j] >= 0 && v.x === 0 && v.y === 0;
    }).length;
    return {
      bars: [...document.querySelectorAll('#histogram rect.bar')].map((b) => Number(b.dataset.count)),
      expected: [...document.querySelectorAll('#histogram circle.binomial')]
          .map((c) => Number(c.dataset.expected)),
      landedShown: Number(number('landed')),
      poured: g.poured,
      landed: g.landed,
      counts: g.counts,
      landedBin: g.landedBin,
      balls,
      resting,
      fixed: g.fixed,
      box: {lower: g.board.lower, upper: g.board.upper},
      edges: g.board.bins.edges,
      binTop: g.board.bins.top,
      audit: g.world.audit(),
      stalled: g.stalled,
      error: document.getElementById('error-line').textContent,
    };
  });
}

const sum = (list) => list.reduce((s, v) => s + v, 0);

test('poured balls land in the bins and the histogram counts exactly the balls landed',
     {timeout: RUN_TIMEOUT_MS + 20000}, async () => {
  const {page, problems} = await openPage(session, 'galton.html?rate=20');
  await page.waitForFunction((n) => window.caromGalton.landed >= n, LANDED_WANTED,
                             {timeout: RUN_TIMEOUT_MS, polling: 200});
  await page.waitForFunction(  // the report after the last landing counted
      (n) => Number(document.querySelector('[data-readout="landed"]').textContent) >= n,
      LANDED_WANTED, {timeout: RUN_TIMEOUT_MS, polling: 50});
  const s = await state(page);
  assert.equal(s.error, '');
  assert.equal(s.stalled, false);
  // The page's two counts of the same thing agree: the bars' total and the readout, drawn in the
  // same frame; the live counts and the live total.
  assert.equal(sum(s.bars), s.landedShown);
  assert.equal(sum(s.counts), s.landed);
  assert.ok(s.landed >= LANDED_WANTED && s.poured >= s.landed, `${s.landed} of ${s.poured}`);
  // Binomial(12, 1/2) times the balls landed: the middle bin's chance is C(12, 6)/2¹² = 924/4096.
  assert.equal(s.expected.length, 13);
  assert.ok(Math.abs(sum(s.expected) - s.landedShown) < 1e-9 * s.landedShown);
  assert.ok(Math.abs(s.expected[6] - s.landedShown * 924 / 4096) < 1e-9 * s.landedShown);
  // Every ball in the box; every landed ball inside the bin it was counted in, below its top.
  for (const [j, p] of s.balls.entries()) {
    assert.ok(p.x > s.box.lower.x && p.x < s.box.upper.x && p.y > s.box.lower.y &&
              p.y < s.box.upper.y, `ball ${j} at (${p.x}, ${p.y}) is outside the box`);
    const bin = s.landedBin[j];
    if (bin < 0) continue;
    assert.ok(p.x > s.edges[bin] && p.x < s.edges[bin + 1] && p.y < s.binTop,
              `ball ${j}, counted in bin ${bin}, is at (${p.x}, ${p.y})`);
  }
  // No step refused, so no landed ball was fixed (replaced by an immovable one); the piles are
  // movable balls that carom has brought to rest.
  assert.equal(s.fixed, 0);
  assert.ok(s.resting > 0, `${s.resting} of ${s.landed} landed balls at rest`);
  assert.equal(s.audit, '');
  await page.screenshot({path: `${OUTPUT}/galton-running.png`, fullPage: true});
  assert.deepEqual(problems, []);
  await page.close();
});

test('the pour stops and starts, and Reset empties the board', {timeout: RUN_TIMEOUT_MS},
     async () => {
  const {page, problems} = await openPage(session, 'galton.html?rate=20');
  await page.waitForFunction(() => window.caromGalton.poured >= 10, null,
                             {timeout: RUN_TIMEOUT_MS, polling: 100});
  await page.click('#pour');
  assert.equal(await page.textContent('#pour'), 'Pour');
  const stopped = await page.evaluate(() => window.caromGalton.poured);
  await page.waitForTimeout(500);
  assert.equal(await page.evaluate(() => window.caromGalton.poured), stopped);
  await page.click('#reset');
  await expectReadout(page, 'poured', '0 of 1000');
  const s = await state(page);
  assert.deepEqual([s.poured, s.landed, sum(s.bars), s.landedShown], [0, 0, 0, 0]);
  await page.click('#pour');
  await page.waitForFunction(() => window.caromGalton.poured >= 3, null,
                             {timeout: RUN_TIMEOUT_MS, polling: 100});
  assert.deepEqual(problems, []);
  await page.close();
});
