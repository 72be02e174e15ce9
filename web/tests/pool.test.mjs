// "Pool": the aim line against closed forms computed here from the balls' places. The ghost ball
// of an aim at ball 1 sits on the aim line where the centres are the two radii apart, and the two
// balls leave as an equal-mass bounce with the table's restitution sends them; a drag sets the
// same aim; an aim at an empty cushion or at a pocket reports it, with the ghost ball a radius
// off the cushion or touching the pocket; a shot along the aim first meets what was predicted,
// at the predicted time and point (the World's own contacts); a click stops every ball, the aim
// comes back, and Rack racks again.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage, readout} from './browser.mjs';
import {mouseDrag} from './drag.mjs';

const TIGHT = 1e-12;  // m: the rounding of a few operations on numbers of about a metre
const SHOT_TIMEOUT_MS = 20000;

let served;
before(async () => { served = await openBrowser(); });
after(async () => { await served?.close(); });

const sub = (a, b) => ({x: a.x - b.x, y: a.y - b.y});
const add = (a, b) => ({x: a.x + b.x, y: a.y + b.y});
const scale = (a, s) => ({x: a.x * s, y: a.y * s});
const dot = (a, b) => a.x * b.x + a.y * b.y;
const cross = (a, b) => a.x * b.y - a.y * b.x;
const norm = (a) => Math.hypot(a.x, a.y);
const unit = (a) => scale(a, 1 / norm(a));

function near(actual, expected, tolerance, what) {
  const gap = norm(sub(actual, expected));
  assert.ok(gap <= tolerance, `${what}: (${actual.x}, ${actual.y}) is ${gap} from ` +
                              `(${expected.x}, ${expected.y})`);
}

// The table as the page holds it: the cue ball's and ball `name`'s place and radius (a potted
// cue ball keeps its name: the cue ball is the page's `cue`).
function table(page, name) {
  return page.evaluate((name) => {
    const pool = window.caromPool;
    const w = pool.world;
    const ball = name === 'cue' ? pool.cue : pool.names.indexOf(name);
    return {
      cue: pool.cue, cueAt: w.position(pool.cue), cueRadius: w.radius(pool.cue),
      ball, ballAt: ball >= 0 ? w.position(ball) : null,
      ballRadius: ball >= 0 ? w.radius(ball) : null,
      restitution: pool.restitution, pockets: w.pockets(), pocketNames: pool.pocketNames,
    };
  }, name);
}

const aim = (page, direction, speed) => page.evaluate(
    ({direction, speed}) => window.caromPool.aim(direction, speed), {direction, speed});

// Where the cue ball's centre is when it first touches ball b moving from c along u: on the
// line, the centres R apart (the smaller root of |c + s·u − b| = R).
function ghostCentre(c, u, b, R) {
  const w = sub(b, c);
  const along = dot(u, w);
  const across = cross(u, w);
  return add(c, scale(u, along - Math.sqrt(R * R - across * across)));
}

async function waitForFirstContact(page) {
  await page.waitForFunction(() => window.caromPool.shot?.first, null,
                             {timeout: SHOT_TIMEOUT_MS});
  return page.evaluate(() => window.caromPool.shot);
}

test('the ghost ball of an aim at ball 1 is where the centres are two radii apart', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, '1');
  // A cut: aimed 25 mm above ball 1's centre, less than the two radii (57 mm).
  const u = unit(sub(add(t.ballAt, {x: 0, y: 0.025}), t.cueAt));
  const speed = 3;
  const p = await aim(page, u, speed);
  assert.equal(p.hit.kind, 'ball');
  assert.equal(p.hit.ball, t.ball);
  const R = t.cueRadius + t.ballRadius;
  const ghost = ghostCentre(t.cueAt, u, t.ballAt, R);
  near(p.hit.center, ghost, TIGHT, 'the ghost ball');
  assert.ok(Math.abs(norm(sub(p.hit.center, t.ballAt)) - R) <= TIGHT, 'the ghost touches ball 1');
  assert.ok(Math.abs(cross(sub(p.hit.center, t.cueAt), u)) <= TIGHT, 'the ghost is on the aim');
  // The object ball leaves along the line of centres (the hit normal reversed), the cue ball
  // keeps its speed across it and (1 − e)/2 of its speed along it: equal masses.
  const n = unit(sub(t.ballAt, ghost));
  near(scale(p.hit.normal, -1), n, TIGHT, 'the normal, reversed');
  const along = dot(scale(u, speed), n);
  const e = t.restitution;
  near(p.objectVelocity, scale(n, (1 + e) / 2 * along), TIGHT, 'ball 1 after the contact');
  near(p.cueVelocity, sub(scale(u, speed), scale(n, (1 + e) / 2 * along)), TIGHT,
       'the cue ball after the contact');
  assert.ok(Math.abs(dot(unit(p.objectVelocity), n) - 1) <= TIGHT);
  // The readout names it and shows the ghost to its digits.
  await page.waitForTimeout(100);
  assert.equal(await readout(page, 'target'), 'ball 1');
  assert.equal(await readout(page, 'ghost'),
               `(${Number(ghost.x.toPrecision(5))}, ${Number(ghost.y.toPrecision(5))})`);
  await page.screenshot({path: `${OUTPUT}/pool-aim.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('a drag from the cue ball sets the aim and its speed', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, '1');
  const target = add(t.ballAt, {x: 0, y: -0.03});
  const screen = await page.evaluate(
      (points) => points.map((q) => window.caromPool.screenPoint(q)), [t.cueAt, target]);
  await mouseDrag(page, screen[0], screen[1]);
  const p = await page.evaluate(() => window.caromPool.prediction);
  // The pointer lands on whole pixels: the direction to a pixel's rounding (about 3 mm in 1.27 m).
  const u = unit(sub(target, t.cueAt));
  const direction = unit(p.velocity);
  assert.ok(Math.abs(cross(direction, u)) < 5e-3, `aim ${JSON.stringify(direction)}`);
  assert.ok(Math.abs(p.speed - 5 * norm(sub(target, t.cueAt))) < 0.05, `speed ${p.speed}`);
  assert.equal(p.hit.kind, 'ball');
  assert.equal(p.hit.ball, t.ball);
  // Whatever the pixel, carom's ghost touches ball 1 on the aim actually set.
  near(p.hit.center, ghostCentre(t.cueAt, direction, t.ballAt, t.cueRadius + t.ballRadius),
       TIGHT, 'the ghost ball');
  await page.waitForTimeout(100);
  assert.equal(await page.textContent('output[for="speed"]'), String(Number(p.speed.toPrecision(3))));
  assert.deepEqual(problems, []);
  await page.close();
});

test('an aim at an empty cushion reports it, and the shot meets it', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, 'cue');
  const speed = 2;
  const p = await aim(page, {x: 0, y: -1}, speed);
  assert.equal(p.hit.kind, 'wall');
  assert.equal(p.hit.boundary, false, 'a cushion, not the box round the table');
  // The bottom cushions run along y = 0: the ghost ball a radius above it, straight below.
  near(p.hit.center, {x: t.cueAt.x, y: t.cueRadius}, TIGHT, 'the ghost ball');
  near(p.hit.point, {x: t.cueAt.x, y: 0}, TIGHT, 'the cushion point');
  // Straight back up at e times the speed.
  near(p.cueVelocity, {x: 0, y: speed * t.restitution}, TIGHT, 'the rebound');
  await page.waitForTimeout(100);
  assert.equal(await readout(page, 'target'), 'bottom-left cushion');
  await page.screenshot({path: `${OUTPUT}/pool-cushion.png`});
  await page.click('#shoot');
  const shot = await waitForFirstContact(page);
  assert.equal(shot.first.kind, 'wall');
  assert.equal(shot.first.wall, p.hit.wall);
  assert.ok(Math.abs(shot.first.time - (t.cueAt.y - t.cueRadius) / speed) <= 1e-12,
            `met at ${shot.first.time}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an aim at a corner pocket reports it; the potted cue ball comes back', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, 'cue');
  const pocket = t.pocketNames.indexOf('bottom-left');
  const p = await aim(page, sub(t.pockets[pocket], t.cueAt), 4);
  assert.equal(p.hit.kind, 'pocket');
  assert.equal(p.hit.pocket, pocket);
  assert.ok(Math.abs(norm(sub(p.hit.center, t.pockets[pocket])) -
                     (t.cueRadius + t.pockets[pocket].radius)) <= TIGHT);
  await page.waitForTimeout(100);
  assert.equal(await readout(page, 'target'), 'pocket bottom-left');
  await page.click('#shoot');
  const shot = await waitForFirstContact(page);
  assert.equal(shot.first.kind, 'pocket');
  assert.equal(shot.first.pocket, pocket);
  // Nothing else moves: the table comes to rest at once and the cue ball is put back.
  await page.waitForFunction(() => !window.caromPool.running, null, {timeout: SHOT_TIMEOUT_MS});
  const back = await table(page, 'cue');
  assert.notEqual(back.cue, t.cue, 'a new ball');
  near(back.cueAt, t.cueAt, 0, 'the cue ball on its spot');
  assert.deepEqual((await page.evaluate(() => window.caromPool.shot)).potted, [t.cue]);
  assert.ok(await page.evaluate(() => window.caromPool.prediction !== null), 'the aim is back');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a shot along the aim first meets the predicted ball; a click stops it; Rack racks',
     async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, '1');
  const u = unit(sub(add(t.ballAt, {x: 0, y: -0.02}), t.cueAt));
  const p = await aim(page, u, 3);
  assert.equal(p.hit.ball, t.ball);
  await page.click('#shoot');
  const shot = await waitForFirstContact(page);
  // The World's first contact of the cue ball: the predicted ball, when and where predicted.
  assert.equal(shot.first.kind, 'ball');
  assert.equal(shot.first.ball, t.ball);
  assert.ok(Math.abs(shot.first.time - p.time) <= 1e-12, `${shot.first.time} vs ${p.time}`);
  near(shot.first.point, p.hit.point, 1e-12, 'the contact point');
  await page.waitForTimeout(100);
  const first = await readout(page, 'first');
  assert.match(first, /^ball 1 at .* \(predicted ball 1 at .*\)$/);
  assert.doesNotMatch(first, /differs/);
  await page.waitForTimeout(500);
  await page.screenshot({path: `${OUTPUT}/pool-running.png`});
  // A click on the table stops every ball where it is; the aim is shown again.
  assert.ok(await page.evaluate(() => window.caromPool.running));
  await page.click('#table');
  const stopped = await page.evaluate(() => {
    const pool = window.caromPool;
    const balls = Array.from(pool.world.snapshot());
    return {running: pool.running, ended: pool.shot.ended, aim: pool.prediction !== null,
            speeds: balls.filter((_, k) => k % 4 === 3), audit: pool.world.audit()};
  });
  assert.equal(stopped.running, false);
  assert.equal(stopped.ended, 'click');
  assert.ok(stopped.aim);
  assert.ok(stopped.speeds.every((s) => s === 0), `speeds ${stopped.speeds}`);
  assert.equal(stopped.audit, '');
  await page.click('#rack');
  await page.waitForTimeout(100);
  assert.equal(await readout(page, 'balls'), '16');
  const racked = await table(page, '1');
  near(racked.cueAt, t.cueAt, 0, 'the cue ball on its spot');
  near(racked.ballAt, t.ballAt, 0, 'ball 1 on its spot');
  assert.deepEqual(problems, []);
  await page.close();
});
