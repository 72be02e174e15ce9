// "Pinball": a launched ball goes up the lane, round the table and down the drain (a sensor that
// removes it), never leaving the table; the total energy (kinetic + potential, as the page shows
// them) never rises between a launch and the next launch or drain but in the frames a flipper
// swings in; a flipper key or button swings it to its stop and back, a flip sends a ball up the
// table, and a ball still drains between raised flippers; the bindings of moving walls; the
// rollovers' score counts their sensors' enters; the space bar launches and Reset clears the
// table.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, eventually, expectReadout, openBrowser, openPage, openTouchPage, readout}
    from './browser.mjs';

// The ball drains after about 10 s of table time; a loaded machine gives fewer frames.
const RUN_TIMEOUT_MS = 120000;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

// The energy log's rule: between one launch or drain and the next the total (kinetic + potential)
// can only fall (every bounce has restitution 0.8, and carom keeps the total along every flight
// and slide), except in a frame a flipper swings in: a swing is an event like a launch, the
// flipper doing work on the ball it hits. Log entries up to `after` (a time) are left out (a ball
// the test put in play). Returns the frames compared and the most the total rose in one frame
// with a swinging flipper.
function checkEnergy(log, after = -Infinity) {
  let compared = 0;
  let flipWork = 0;
  for (let k = 1; k < log.length; ++k) {
    const [a, b] = [log[k - 1], log[k]];
    if (a.time <= after) continue;
    if (a.launched !== b.launched || a.drained !== b.drained) continue;
    if (a.flips !== b.flips || b.swinging) {
      flipWork = Math.max(flipWork, b.total - a.total);
      continue;
    }
    assert.ok(b.total <= a.total + 1e-9 * Math.abs(a.total),
              `the total energy rose from ${a.total} to ${b.total} at t = ${b.time}`);
    ++compared;
  }
  return {compared, flipWork};
}

// Flipper `side`'s tip (0 left, 1 right) where it is now, where it rests and where its up stop
// is: the rest tip turned by the swing about the pivot (the left counter-clockwise).
function flipperTips(page, side) {
  return page.evaluate((side) => {
    const p = window.caromPinball;
    const rest = p.table.flippers[side];
    const angle = (side === 0 ? 1 : -1) * p.flipperSwing;
    const [dx, dy] = [rest.b.x - rest.a.x, rest.b.y - rest.a.y];
    const id = p.flipperIds[side];
    return {
      now: p.world.wall_segment(id).b,
      rest: rest.b,
      up: {x: rest.a.x + dx * Math.cos(angle) - dy * Math.sin(angle),
           y: rest.a.y + dx * Math.sin(angle) + dy * Math.cos(angle)},
      moving: p.world.wall_motion(id).duration > 0,
    };
  }, side);
}

const near = (p, q) => Math.abs(p.x - q.x) < 1e-9 && Math.abs(p.y - q.y) < 1e-9;

// Waits until flipper `side`'s tip stands still at its up stop or at rest (`where`).
async function tipComesTo(page, side, where) {
  let tips;
  await eventually(async () => {
    tips = await flipperTips(page, side);
    return near(tips.now, tips[where]) && !tips.moving;
  }, () => `flipper ${side}'s tip is at (${tips.now.x}, ${tips.now.y}), not ${where} at ` +
           `(${tips[where].x}, ${tips[where].y})`);
  return tips;
}

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
  // Between the launch and the drain the total can only fall (no flipper moved).
  const {compared} = checkEnergy(await page.evaluate(() => window.caromPinball.energyLog));
  assert.ok(compared > 100, `${compared} frames compared`);
  await expectReadout(page, 'drained', '1');
  assert.equal(await readout(page, 'in_play'), '0');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a flipper key swings it up, it cradles a ball, and a second flip sends the ball up the table',
     async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  const tip = async () => (await flipperTips(page, 0)).now;
  const {rest, up: stop} = await flipperTips(page, 0);
  assert.ok(near(await tip(), rest), 'the flipper starts at rest');
  await page.keyboard.down('z');
  // Turned up about its pivot to its stop exactly (the swing ends inside a frame, no overshoot),
  // the tip 2.6 diameters higher, and standing still there.
  await tipComesTo(page, 0, 'up');
  assert.ok(stop.y > rest.y + 2.4, `the stop is at ${stop.y}`);
  // A ball dropped onto the raised flipper rolls down it into the cradle by the slope wall.
  const [ball, dropTime] = await page.evaluate(() => {
    const p = window.caromPinball;
    return [p.dropBall({x: 7.5, y: 8}), p.world.time()];
  });
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
  // From here the page runs frames only when told, so that the time between letting go and the
  // second flip is the same on a loaded machine as on an idle one.
  await page.evaluate(() => window.caromPinball.pause());
  // Let go: the flipper drops back to rest within 9 frames, and the ball falls onto it.
  await page.keyboard.up('z');
  await page.evaluate(() => window.caromPinball.advanceFrames(9));
  const back = await tip();
  assert.ok(Math.abs(back.x - rest.x) < 1e-9 && Math.abs(back.y - rest.y) < 1e-9,
            `the tip came back to (${back.x}, ${back.y}), not (${rest.x}, ${rest.y})`);
  // Flip again: the ball, rolling on the flipper, is struck and goes up the table.
  const before = await state();
  assert.equal(before.audit, '');
  assert.ok(Math.abs(before.v.y) < 5, `the ball was nearly still on the flipper: ${before.v.y}`);
  await page.keyboard.down('z');
  // Two seconds of table time, frame by frame.
  const flight = await page.evaluate((i) => window.caromPinball.advanceFrames(120, i), ball);
  const highest = Math.max(...flight.map((s) => s.p.y));
  const fastestUp = Math.max(...flight.map((s) => s.v.y));
  assert.ok(highest >= 12, `the flipped ball rose only to ${highest}`);
  // Rising from the cradle (y ≈ 5.5) past 12 under g = 40 takes an upward speed over 22.
  assert.ok(fastestUp > 15, `the flipped ball's upward speed was at most ${fastestUp}`);
  assert.equal((await state()).audit, '');
  await page.evaluate(() => window.caromPinball.resume());
  await page.keyboard.up('z');
  // The log's rule holds from the drop on outside the swings, and the flip did work on the ball:
  // it rose in the swinging frame by far more than any rounding.
  const {compared, flipWork} =
      checkEnergy(await page.evaluate(() => window.caromPinball.energyLog), dropTime);
  assert.ok(compared > 30, `${compared} frames compared`);
  assert.ok(flipWork > 100, `the flip added only ${flipWork} to the total energy`);
  await page.screenshot({path: `${OUTPUT}/pinball-flipped.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('a Flip button holds its flipper up while pressed, and a ball drains between raised flippers',
     async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  await page.hover('#flip-right');
  await page.mouse.down();
  await page.keyboard.down('ArrowLeft');
  await tipComesTo(page, 1, 'up');
  await tipComesTo(page, 0, 'up');
  // Straight down the middle, between the raised tips: the drain takes it.
  await page.evaluate(() => {
    const p = window.caromPinball;
    p.dropBall({x: p.table.upper.x / 2 - 0.75, y: 10});
  });
  await page.waitForFunction(() => window.caromPinball.drained === 1, null, {timeout: 60000});
  assert.deepEqual(await page.evaluate(() => window.caromPinball.inPlay), []);
  await page.mouse.up();
  await page.keyboard.up('ArrowLeft');
  for (const side of [0, 1]) await tipComesTo(page, side, 'rest');
  // A key let go while the page has no focus: leaving the page drops the flipper all the same.
  await page.keyboard.down('z');
  await tipComesTo(page, 0, 'up');
  await page.evaluate(() => window.dispatchEvent(new Event('blur')));
  await tipComesTo(page, 0, 'rest');
  await page.keyboard.up('z');
  assert.deepEqual(problems, []);
  await page.close();
});

test('on a touch screen a finger held on a Flip button holds the flipper up, even as it slides',
     async () => {
  const {context, page, problems} = await openTouchPage(session, 'pinball.html');
  const box = await page.locator('#flip-left').boundingBox();
  const [x, y] = [box.x + box.width / 2, box.y + box.height / 2];
  const touch = await context.newCDPSession(page);
  const finger = (type, dx = 0) => touch.send('Input.dispatchTouchEvent', {
    type, touchPoints: type === 'touchEnd' ? [] : [{x: x + dx, y: y + dx}]});
  await finger('touchStart');
  await tipComesTo(page, 0, 'up');
  // A slide that would start a scroll (and cancel the press) where the page may scroll. Frames
  // are counted from here: a cancelled press would bring the tip back to rest within 9.
  await page.evaluate(() => window.caromPinball.pause());
  for (let d = 2; d <= 12; d += 2) await finger('touchMove', d);
  await page.evaluate(() => window.caromPinball.advanceFrames(12));
  const held = await flipperTips(page, 0);
  assert.ok(near(held.now, held.up), `the tip is at (${held.now.x}, ${held.now.y})`);
  await finger('touchEnd');
  await page.evaluate(() => window.caromPinball.advanceFrames(12));
  const released = await flipperTips(page, 0);
  assert.ok(near(released.now, released.rest),
            `the tip is at (${released.now.x}, ${released.now.y})`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('a moving wall from JavaScript: its motion, its drawing where it is now, and refusals',
     async () => {
  const {page, problems} = await openPage(session, 'index.html');
  const outcome = await page.evaluate(async () => {
    const {carom} = await import('./js/carom.js');
    const world = new carom.DrawnWorld({boundary: carom.Boundary.open, lower: {x: -5, y: -5},
                                        upper: {x: 5, y: 5}, restitution: 1, collapse_time: 0,
                                        cell_size: 0, gravity: {x: 0, y: 0}, rest_height: 1e-3});
    const out = {};
    try {
      const wall = world.add_segment({a: {x: 0, y: 0}, b: {x: 2, y: 0}});
      const sensor = world.add_sensor_segment({a: {x: 3, y: 3}, b: {x: 4, y: 3}}, false);
      world.add_arc({center: {x: -3, y: -3}, radius: 1, start_angle: 0, end_angle: 1});
      const arc = sensor + 1;
      const still = {velocity: {x: 0, y: 0}, angular_velocity: 0, pivot: {x: 0, y: 0},
                     duration: 0};
      out.before = world.wall_motion(wall);
      const turn = {velocity: {x: 0, y: 0}, angular_velocity: Math.PI / 2, pivot: {x: 0, y: 0},
                    duration: Infinity};
      world.set_wall_motion(wall, turn);
      out.forever = world.wall_motion(wall).duration;
      world.set_wall_motion(wall, {...turn, duration: 1});
      world.step(0.5);
      out.half = {motion: world.wall_motion(wall), drawn: world.segments()[0]};
      world.step(1);
      out.end = {motion: world.wall_motion(wall), drawn: world.segments()[0],
                 segment: world.wall_segment(wall)};
      out.still = still;
      const refusal = (f) => {
        try {
          f();
        } catch (error) {
          return error instanceof Error ? error.message : `not an Error: ${error}`;
        }
        return 'no error';
      };
      out.errors = {
        sensor: refusal(() => world.set_wall_motion(sensor, turn)),
        nan: refusal(() => world.set_wall_motion(wall, {...turn, angular_velocity: NaN})),
        negative: refusal(() => world.set_wall_motion(wall, {...turn, duration: -1})),
        arc: refusal(() => world.wall_segment(arc)),
        id: refusal(() => world.wall_motion(-1)),
      };
      out.after = world.wall_motion(wall).duration;  // the module still answers
    } finally {
      world.delete();
    }
    return out;
  });
  assert.deepEqual(outcome.before, outcome.still);
  assert.equal(outcome.forever, Infinity);
  assert.ok(Math.abs(outcome.half.motion.duration - 0.5) < 1e-12, JSON.stringify(outcome.half));
  assert.equal(outcome.half.motion.angular_velocity, Math.PI / 2);
  // Half way: turned by π/4; segments() draws it where it is now.
  const s = Math.SQRT1_2 * 2;
  assert.ok(near(outcome.half.drawn.b, {x: s, y: s}), JSON.stringify(outcome.half.drawn));
  // The motion ended at its duration, a quarter turn, and the wall stands still there.
  assert.deepEqual(outcome.end.motion, outcome.still);
  assert.ok(near(outcome.end.drawn.b, {x: 0, y: 2}), JSON.stringify(outcome.end.drawn));
  assert.deepEqual(outcome.end.segment, outcome.end.drawn);
  const {errors} = outcome;
  assert.match(errors.sensor, /^carom::World::set_wall_motion: wall = 1: is a sensor/);
  assert.match(errors.nan, /^carom::World::set_wall_motion: motion\.angular_velocity = nan/i);
  assert.match(errors.negative, /^carom::World::set_wall_motion: motion\.duration = -1/);
  assert.match(errors.arc, /^carom::DrawnWorld::wall_segment: wall = 2: must name a segment/);
  assert.match(errors.id, /^carom::DrawnWorld::wall_motion: wall = -1: must be a wall id >= 0/);
  assert.equal(outcome.after, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the space bar launches, the readout adds up, and Reset clears the table', async () => {
  const {page, problems} = await openPage(session, 'pinball.html');
  await page.keyboard.press('Space');
  await expectReadout(page, 'launched', '1');
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
  await expectReadout(page, 'launched', '0');
  assert.equal(await readout(page, 'in_play'), '0');
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
