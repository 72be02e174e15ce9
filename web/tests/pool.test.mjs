// "Pool": a table with friction, checked against closed forms computed here. The ghost ball of
// an aim at ball 1 sits on the aim line where the centres are the two radii apart, and the shot
// run to rest on a copy first meets ball 1 there; the cue's strike gives the cue ball 2·M/(M + m)
// of the cue's speed; a drag sets the aim; a stun shot at a cushion meets it at the time of a
// sliding ball's closed form, and a strike 2/5 of the radius above the centre rolls at once and
// meets it at a rolling ball's; a pocket takes the cue ball and the page puts it back; draw
// brings the cue ball back from a full hit where a stun shot leaves it; the shot itself goes
// frame by frame exactly as predicted (same first contact, same contacts, every ball at rest in
// the same place to the bit), passing through sliding and rolling; a click stops every ball,
// spin and all; Rack racks again.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, eventually, expectReadout, openBrowser, openPage, readout} from './browser.mjs';
import {mouseDrag} from './drag.mjs';

const TIGHT = 1e-12;  // m: the rounding of a few operations on numbers of about a metre
// s or m: a contact time or place the World finds by certified root isolation on its parabolas,
// against the same quantity computed here in closed form (each rounds to about 10⁻¹⁵; the
// isolation's own tolerance is far below this)
const CLOSE = 1e-9;
const SHOT_TIMEOUT_MS = 60000;
const CUE_MASS = 0.54;  // carom::CueStrike's default, in kg

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
// cue ball keeps its name: the cue ball is the page's `cue`), and the cloth.
function table(page, name) {
  return page.evaluate((name) => {
    const pool = window.caromPool;
    const w = pool.world;
    const ball = name === 'cue' ? pool.cue : pool.names.indexOf(name);
    return {
      cue: pool.cue, cueAt: w.position(pool.cue), cueRadius: w.radius(pool.cue),
      cueMass: w.mass(pool.cue),
      ball, ballAt: ball >= 0 ? w.position(ball) : null,
      ballRadius: ball >= 0 ? w.radius(ball) : null,
      cloth: w.table(), pockets: w.pockets(), pocketNames: pool.pocketNames,
    };
  }, name);
}

// The prediction for an aim (and a tip, in shares of the radius), without its paths unless asked.
const aim = (page, direction, speed, tip = {side: 0, height: 0}, paths = false) => page.evaluate(
    ({direction, speed, tip, paths}) => {
      const pool = window.caromPool;
      pool.setTip(tip.side, tip.height);
      const p = pool.aim(direction, speed);
      return paths ? p : {...p, paths: undefined};
    }, {direction, speed, tip, paths});

// Where the cue ball's centre is when it first touches ball b moving from c along u: on the
// line, the centres R apart (the smaller root of |c + s·u − b| = R).
function ghostCentre(c, u, b, R) {
  const w = sub(b, c);
  const along = dot(u, w);
  const across = cross(u, w);
  return add(c, scale(u, along - Math.sqrt(R * R - across * across)));
}

// When a ball launched at v0 by a level strike through its centre (sliding, no spin) has gone d
// along a straight line: it slides with deceleration μs·g until 2·v0/(7·μs·g), when it rolls at
// 5/7 of v0, then rolls with deceleration μr·g.
function stunTime(v0, d, cloth) {
  const slide = cloth.sliding_friction * cloth.g;
  const rollingFrom = 2 * v0 / (7 * slide);
  const slid = v0 * rollingFrom - slide * rollingFrom * rollingFrom / 2;
  if (d <= slid) return (v0 - Math.sqrt(v0 * v0 - 2 * slide * d)) / slide;
  return rollingFrom + rollTime(5 / 7 * v0, d - slid, cloth);
}

// When a rolling ball at v0 has gone d: deceleration μr·g.
function rollTime(v0, d, cloth) {
  const roll = cloth.rolling_friction * cloth.g;
  return (v0 - Math.sqrt(v0 * v0 - 2 * roll * d)) / roll;
}

async function waitForFirstContact(page) {
  await page.waitForFunction(() => window.caromPool.shot?.first, null,
                             {timeout: SHOT_TIMEOUT_MS});
  return page.evaluate(() => window.caromPool.shot);
}

test('the ghost ball of an aim at ball 1 is where the centres are two radii apart, and the ' +
     'shot meets ball 1 there', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, '1');
  assert.ok(t.cloth, 'the table has a cloth');
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
  // The cue (mass M, restitution 1) through the centre gives the ball 2·M/(M + m) of its speed
  // along the aim, and no spin: it starts sliding.
  const launched = 2 * CUE_MASS / (CUE_MASS + t.cueMass) * speed;
  near(p.launch.velocity, scale(u, launched), TIGHT * launched, 'the launch velocity');
  assert.deepEqual(p.launch.spin, {x: 0, y: 0, z: 0});
  assert.equal(p.launch.state, 'sliding');
  // Run to rest on a copy, the cue ball (sliding straight, friction along its velocity) first
  // meets ball 1 at the ghost ball's touching point, after the closed form's time.
  assert.equal(p.first.kind, 'ball');
  assert.equal(p.first.ball, t.ball);
  near(p.first.point, p.hit.point, CLOSE, 'the contact point');
  const travelled = norm(sub(ghost, t.cueAt));
  assert.ok(Math.abs(p.first.time - stunTime(launched, travelled, t.cloth)) <= CLOSE,
            `met at ${p.first.time}`);
  assert.ok(p.rests, 'the shot comes to rest');
  // The readout names it and shows the ghost to its digits.
  await expectReadout(page, 'target', 'ball 1');
  assert.equal(await readout(page, 'ghost'),
               `(${Number(ghost.x.toPrecision(5))}, ${Number(ghost.y.toPrecision(5))})`);
  assert.match(await readout(page, 'launch'), /^4\.56 m\/s, sliding$/);
  assert.match(await readout(page, 'prediction'), /^\d+ contacts, rest after [\d.]+ s/);
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
  const p = await page.evaluate(() => ({...window.caromPool.prediction, paths: undefined}));
  // The pointer lands on whole pixels: the direction to a pixel's rounding (about 3 mm in 1.27 m).
  const u = unit(sub(target, t.cueAt));
  const direction = unit(p.velocity);
  assert.ok(Math.abs(cross(direction, u)) < 5e-3, `aim ${JSON.stringify(direction)}`);
  assert.ok(Math.abs(p.speed - 4 * norm(sub(target, t.cueAt))) < 0.05, `speed ${p.speed}`);
  assert.equal(p.hit.kind, 'ball');
  assert.equal(p.hit.ball, t.ball);
  // Whatever the pixel, carom's ghost touches ball 1 on the aim actually set, and the strike
  // goes that way.
  near(p.hit.center, ghostCentre(t.cueAt, direction, t.ballAt, t.cueRadius + t.ballRadius),
       TIGHT, 'the ghost ball');
  assert.ok(Math.abs(p.strike.direction - Math.atan2(direction.y, direction.x)) <= TIGHT);
  const speedShown = String(Number(p.speed.toPrecision(3)));
  let speedText;
  await eventually(async () => (speedText = await page.textContent('output[for="speed"]')) ===
                                   speedShown,
                   () => `the speed shows ${speedText}, not ${speedShown}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a stun shot meets an empty cushion when a sliding ball would; the shot does the same',
     async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, 'cue');
  const p = await aim(page, {x: 0, y: -1}, 2);
  assert.equal(p.hit.kind, 'wall');
  assert.equal(p.hit.boundary, false, 'a cushion, not the box round the table');
  // The bottom cushions run along y = 0: the ghost ball a radius above it, straight below.
  near(p.hit.center, {x: t.cueAt.x, y: t.cueRadius}, TIGHT, 'the ghost ball');
  near(p.hit.point, {x: t.cueAt.x, y: 0}, TIGHT, 'the cushion point');
  assert.equal(p.first.kind, 'wall');
  assert.equal(p.first.wall, p.hit.wall);
  const v0 = norm(p.launch.velocity);
  const expected = stunTime(v0, t.cueAt.y - t.cueRadius, t.cloth);
  assert.ok(Math.abs(p.first.time - expected) <= CLOSE, `met at ${p.first.time}, not ${expected}`);
  await expectReadout(page, 'target', 'bottom-left cushion');
  await page.screenshot({path: `${OUTPUT}/pool-cushion.png`});
  await page.click('#shoot');
  await page.waitForFunction(() => window.caromPool.shot?.first, null, {timeout: SHOT_TIMEOUT_MS});
  const shot = await page.evaluate(() => window.caromPool.shot.first);
  assert.equal(shot.kind, 'wall');
  assert.equal(shot.wall, p.hit.wall);
  assert.equal(shot.time, p.first.time, 'the same time to the bit');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a strike 2/5 of the radius above the centre rolls at once; the tip diagram sets follow, ' +
     'draw and English', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, 'cue');
  // Rolling from the strike (ω·R = v, topspin about the axis left of the aim), it meets the
  // bottom cushion when a rolling ball would.
  const p = await aim(page, {x: 0, y: -1}, 1, {side: 0, height: 0.4});
  assert.equal(p.launch.state, 'rolling');
  const v0 = norm(p.launch.velocity);
  // Along −y, topspin turns about +x (the axis ẑ × u).
  assert.ok(Math.abs(p.launch.spin.x * t.cueRadius - v0) <= TIGHT * v0,
            `spin ${JSON.stringify(p.launch.spin)} at ${v0} m/s`);
  const expected = rollTime(v0, t.cueAt.y - t.cueRadius, t.cloth);
  assert.ok(Math.abs(p.first.time - expected) <= CLOSE, `met at ${p.first.time}, not ${expected}`);
  // Pressed on the diagram: above the centre is topspin, below backspin, right of it right
  // English (the right side pushed forward: counter-clockwise seen from above, spin about z
  // above 0), and farther than half the radius is brought back to it.
  const box = await page.locator('#tip').boundingBox();
  const [cx, cy, r] = [box.x + box.width / 2, box.y + box.height / 2, 0.45 * box.width];
  const pressed = async (dx, dy) => {
    await page.mouse.click(cx + dx * r, cy - dy * r);
    return page.evaluate(() => ({tip: window.caromPool.tip,
                                 launch: window.caromPool.prediction.launch}));
  };
  const follow = await pressed(0, 0.3);
  assert.ok(follow.tip.height > 0.25 && Math.abs(follow.tip.side) < 0.05);
  assert.ok(follow.launch.spin.x > 0, `follow: spin ${JSON.stringify(follow.launch.spin)}`);
  const draw = await pressed(0, -0.3);
  assert.ok(draw.launch.spin.x < 0, `draw: spin ${JSON.stringify(draw.launch.spin)}`);
  const english = await pressed(0.9, 0);
  assert.ok(Math.abs(norm({x: english.tip.side, y: english.tip.height}) - 0.5) <= 1e-12);
  assert.ok(english.launch.spin.z > 0, `right English: spin ${JSON.stringify(english.launch.spin)}`);
  await expectReadout(page, 'tip', '0.5 R right');
  await page.click('#centre-tip');
  assert.deepEqual(await page.evaluate(() => window.caromPool.tip), {side: 0, height: 0});
  // From the keyboard: the arrows move the tip a twentieth of the radius.
  await page.focus('#tip');
  await page.keyboard.press('ArrowUp');
  assert.ok(Math.abs((await page.evaluate(() => window.caromPool.tip)).height - 0.05) <= 1e-15);
  // A full hit on ball 1 (which meets the rack at once and comes back a little): half a second
  // after the contact, draw has brought the cue ball well back, and follow has carried it on
  // past where a stun shot leaves it.
  const one = await table(page, '1');
  const full = unit(sub(one.ballAt, one.cueAt));
  const halfSecondOn = async (height) => {
    const q = await aim(page, full, 3, {side: 0, height}, true);
    assert.equal(q.first.ball, one.ball);
    // paths[i][k] is ball i's place k frames after the strike.
    return q.paths[one.cue][Math.ceil(q.first.time * 60) + 30].x;
  };
  const [drawn, stun, followed] =
      [await halfSecondOn(-0.5), await halfSecondOn(0), await halfSecondOn(0.5)];
  assert.ok(drawn < stun - 0.1, `draw left the cue ball at x = ${drawn}, a stun shot at ${stun}`);
  assert.ok(followed > stun + 0.05, `follow left it at x = ${followed}, a stun shot at ${stun}`);
  await page.screenshot({path: `${OUTPUT}/pool-draw.png`});
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
  assert.equal(p.first.kind, 'pocket');
  assert.deepEqual(p.potted, [t.cue]);
  await expectReadout(page, 'target', 'pocket bottom-left');
  await page.click('#shoot');
  // Nothing else moves: the table comes to rest when the pocket takes the cue ball, and the cue
  // ball is put back.
  await page.waitForFunction(() => window.caromPool.shot?.ended, null, {timeout: SHOT_TIMEOUT_MS});
  const shot = await page.evaluate(() => window.caromPool.shot);
  assert.equal(shot.ended, 'rest');
  assert.equal(shot.first.kind, 'pocket');
  assert.equal(shot.first.pocket, pocket);
  assert.deepEqual(shot.potted, [t.cue]);
  assert.equal(shot.asPredicted, true);
  const back = await table(page, 'cue');
  assert.notEqual(back.cue, t.cue, 'a new ball');
  near(back.cueAt, t.cueAt, 0, 'the cue ball on its spot');
  assert.ok(await page.evaluate(() => window.caromPool.prediction !== null), 'the aim is back');
  assert.deepEqual(problems, []);
  await page.close();
});

test('a click stops a shot, spin and all; Rack racks; a break goes exactly as predicted, ' +
     'through sliding and rolling to rest', async () => {
  const {page, problems} = await openPage(served, 'pool.html');
  const t = await table(page, '1');
  // A click on the table stops every ball where it is, spin and all; the aim is shown again.
  await aim(page, unit(sub(t.ballAt, t.cueAt)), 6, {side: 0.3, height: -0.3});
  await page.click('#shoot');
  await page.waitForFunction(() => window.caromPool.shot?.frames >= 10, null,
                             {timeout: SHOT_TIMEOUT_MS});
  assert.ok(await page.evaluate(() => window.caromPool.running), 'still running');
  await page.click('#table');
  const stopped = await page.evaluate(() => {
    const pool = window.caromPool;
    const balls = Array.from(pool.world.snapshot());
    return {running: pool.running, ended: pool.shot.ended, aim: pool.prediction !== null,
            speeds: balls.filter((_, k) => k % 4 === 3), atRest: pool.world.at_rest(),
            audit: pool.world.audit()};
  });
  assert.equal(stopped.running, false);
  assert.equal(stopped.ended, 'click');
  assert.ok(stopped.aim);
  assert.ok(stopped.speeds.every((s) => s === 0), `speeds ${stopped.speeds}`);
  assert.ok(stopped.atRest, 'no ball spins on');
  assert.equal(stopped.audit, '');
  await page.click('#rack');
  await expectReadout(page, 'balls', '16');
  const racked = await table(page, '1');
  near(racked.cueAt, t.cueAt, 0, 'the cue ball on its spot');
  near(racked.ballAt, t.ballAt, 0, 'ball 1 on its spot');
  const p = await aim(page, unit(sub(add(t.ballAt, {x: 0, y: 0.004}), t.cueAt)), 7);
  assert.equal(p.first.ball, t.ball);
  assert.ok(p.rests && p.contacts > 15, `${p.contacts} contacts`);
  await page.click('#shoot');
  await page.waitForFunction(() => window.caromPool.shot?.ended, null, {timeout: SHOT_TIMEOUT_MS});
  const shot = await page.evaluate(() => {
    const pool = window.caromPool;
    const w = pool.world;
    return {...pool.shot, predicted: undefined, atRest: w.at_rest(), audit: w.audit()};
  });
  // The World's own run, frame by frame: the predicted first contact, when and where, as many
  // contacts and frames, and every ball at rest where the copy left it, to the bit.
  assert.equal(shot.ended, 'rest');
  assert.equal(shot.first.kind, 'ball');
  assert.equal(shot.first.ball, t.ball);
  assert.equal(shot.first.time, p.first.time);
  assert.deepEqual(shot.first.point, p.first.point);
  assert.equal(shot.contacts, p.contacts);
  assert.equal(shot.frames, p.frames);
  assert.deepEqual(shot.end, p.end);
  assert.deepEqual(shot.potted, p.potted);
  assert.equal(shot.asPredicted, true);
  assert.ok(shot.atRest);
  assert.equal(shot.audit, '');
  for (const state of ['sliding', 'rolling', 'stationary']) {
    assert.ok(shot.states.includes(state), `no ball was ever ${state}: ${shot.states}`);
  }
  await expectReadout(page, 'as_predicted', /^yes/);
  assert.match(await readout(page, 'first'), /^ball 1 at .* \(predicted ball 1 at .*\)$/);
  assert.equal(await readout(page, 'shot'), 'every ball at rest');
  await page.screenshot({path: `${OUTPUT}/pool-rest.png`});
  assert.deepEqual(problems, []);
  await page.close();
});
