// "Pinball": a launched ball goes up the lane, round the table and down the drain (a sensor that
// removes it), never leaving the table; the total energy (kinetic + potential, as the page shows
// them) never rises between a launch and the next launch or drain; the rollovers' score counts
// their sensors' enters; the space bar launches and Reset clears the table.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage, readout} from './browser.mjs';

// The ball drains after about 10 s of table time; a loaded machine gives fewer frames.
const RUN_TIMEOUT_MS = 120000;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

function table(page) {
  return page.evaluate(() => {
    const p = window.caromPinball;
    return {
      balls: p.inPlay.map((i) => p.world.position(i)),
      launched: p.launched,
      drained: p.drained,
      score: p.score,
      audit: p.world.audit(),
      upper: p.table.upper,
    };
  });
}

test('a launched ball goes round the table, stays on it, loses energy only in bounces and drains',
     {timeout: RUN_TIMEOUT_MS + 20000}, async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  await page.click('#launch');
  let seen = await table(page);
  assert.equal(seen.launched, 1);
  let highest = 0;
  const deadline = Date.now() + RUN_TIMEOUT_MS;
  while (seen.drained === 0) {
    assert.ok(Date.now() < deadline, 'the ball never drained');
    assert.equal(seen.audit, '');
    for (const b of seen.balls) {
      assert.ok(b.x > 0 && b.x < seen.upper.x && b.y > 0 && b.y < seen.upper.y,
                `a ball at (${b.x}, ${b.y}) is off the table`);
      highest = Math.max(highest, b.y);
    }
    if (highest > 30 && seen.balls.length) {
      await page.screenshot({path: `${OUTPUT}/pinball-running.png`});
    }
    await page.waitForTimeout(100);
    seen = await table(page);
  }
  assert.ok(highest > 25, `the ball went up the lane and round the top: highest ${highest}`);
  assert.equal(seen.balls.length, 0);
  assert.equal(seen.score % 100, 0, `score ${seen.score}`);
  // The drain took the ball at the line: no ball centre ever went below it by more than its
  // radius (the drain sensor removes it as its edge reaches the line).
  const gone = await page.evaluate(() => window.caromPinball.world.ball_count());
  assert.equal(gone, 6, 'only the bumpers and posts are left');
  // Between the launch and the drain the total can only fall: every bounce has restitution 0.8,
  // and carom keeps kinetic + potential energy along every flight and slide.
  const log = await page.evaluate(() => window.caromPinball.energyLog);
  let compared = 0;
  for (let k = 1; k < log.length; ++k) {
    const [a, b] = [log[k - 1], log[k]];
    if (a.launched !== b.launched || a.drained !== b.drained) continue;
    if (a.flips !== b.flips || b.swinging) continue;  // a swinging flipper does work
    assert.ok(b.total <= a.total + 1e-9 * Math.abs(a.total),
              `the total energy rose from ${a.total} to ${b.total} at t = ${b.time}`);
    ++compared;
  }
  assert.ok(compared > 100, `${compared} frames compared`);
  await page.waitForTimeout(200);
  assert.equal(await readout(page, 'drained'), '1');
  assert.equal(await readout(page, 'in_play'), '0');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a flipper key swings it up, it cradles a ball, and a second flip sends the ball up the table',
     async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  const tip = () => page.evaluate(() => {
    const p = window.caromPinball;
    return p.world.wall_segment(p.flipperIds[0]).b;
  });
  const rest = await tip();
  await page.keyboard.down('z');
  await page.waitForTimeout(300);
  const up = await tip();
  // Turned 0.84 rad up about its pivot: the tip rose by 2.6 diameters.
  assert.ok(up.y > rest.y + 2.4, `the tip rose from ${rest.y} to ${up.y}`);
  // A ball dropped onto the raised flipper rolls down it into the cradle by the slope wall.
  const ball = await page.evaluate(() => window.caromPinball.dropBall({x: 7.5, y: 8}));
  const state = () => page.evaluate((i) => {
    const w = window.caromPinball.world;
    return {p: w.position(i), v: w.velocity(i), audit: w.audit()};
  }, ball);
  await page.waitForTimeout(300);  // it starts at rest: let it fall first
  let seen = await state();
  const deadline = Date.now() + 20000;
  while (Math.hypot(seen.v.x, seen.v.y) > 0.01 || seen.p.y > 7.5) {
    assert.ok(Date.now() < deadline, `the ball never came to rest: at (${seen.p.x}, ${seen.p.y})`);
    assert.equal(seen.audit, '');
    await page.waitForTimeout(100);
    seen = await state();
  }
  assert.ok(seen.p.x < 7 && seen.p.y > 4.5, `cradled at (${seen.p.x}, ${seen.p.y})`);
  // Let go: the flipper drops back to rest, and the ball falls onto it.
  await page.keyboard.up('z');
  await page.waitForTimeout(150);
  const back = await tip();
  assert.ok(Math.abs(back.x - rest.x) < 1e-9 && Math.abs(back.y - rest.y) < 1e-9,
            `the tip came back to (${back.x}, ${back.y}), not (${rest.x}, ${rest.y})`);
  // Flip again: the ball, rolling on the flipper, is struck and goes up the table.
  await page.keyboard.down('z');
  let highest = 0;
  const flight = Date.now() + 5000;
  while (highest < 12 && Date.now() < flight) {
    await page.waitForTimeout(50);
    seen = await state();
    assert.equal(seen.audit, '');
    highest = Math.max(highest, seen.p.y);
  }
  assert.ok(highest >= 12, `the flipped ball rose only to ${highest}`);
  await page.keyboard.up('z');
  await page.screenshot({path: `${OUTPUT}/pinball-flipped.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('the space bar launches, the readout adds up, and Reset clears the table', async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  await page.keyboard.press('Space');
  await page.waitForTimeout(400);
  // In one go: the readout changes every few frames.
  const texts = await page.evaluate(() => Object.fromEntries(
      [...document.querySelectorAll('[data-readout]')].map((e) => [e.dataset.readout,
                                                                  e.textContent])));
  assert.equal(texts.launched, '1');
  assert.equal(texts.in_play, '1');
  const total = Number(texts.kinetic) + Number(texts.potential);
  assert.ok(Math.abs(Number(texts.total) - total) < 1e-5 * Math.abs(total), JSON.stringify(texts));
  assert.ok(Number(texts.potential) > 0, 'a ball above the table\'s foot has potential energy');
  await page.click('#reset');
  await page.waitForTimeout(200);
  assert.equal(await readout(page, 'in_play'), '0');
  assert.equal(await readout(page, 'launched'), '0');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a ball dropped through a rollover scores once, however fast',
     {timeout: 60000}, async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  await page.click('#reset');
  // Straight down through the left rollover's middle at 200 diameters a second: it crosses the
  // sensor line (one diameter thick, with the ball) in a fraction of a frame.
  const start = await page.evaluate(() => {
    const p = window.caromPinball;
    const lane = p.table.rollovers[0];
    const x = (lane.a.x + lane.b.x) / 2;
    p.world.add_ball({x, y: 33}, {x: 0, y: -200}, 0.3, 1);
    return p.score;
  });
  assert.equal(start, 0);
  await page.waitForFunction(() => window.caromPinball.score > 0, null, {timeout: 20000});
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.caromPinball.score), 100);
  assert.equal(await readout(page, 'score'), '100');
  assert.deepEqual(problems, []);
  await page.close();
});
