// Bad arguments: the library's carom::InvalidArgument reaches JavaScript as an Error carrying the
// library's own message (web/bindings/js_error.hpp), and the module keeps working afterwards; the
// table's calls refuse a bad strike or spin by name, and a copy of a table goes on by itself.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {openBrowser, openPage} from './browser.mjs';

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

test('a bad radius is a JavaScript Error naming the argument and value', async () => {
  const {page, problems} = await openPage(session, 'index.html');
  const outcome = await page.evaluate(async () => {
    const {carom} = await import('./js/carom.js');
    const ball = (x, radius) => ({center: {x, y: 0}, radius});
    let message = null;
    try {
      carom.sweep_ball_ball(ball(0, -1), {x: 1, y: 0}, ball(5, 1), {x: 0, y: 0});
    } catch (error) {
      message = error instanceof Error ? error.message : `not an Error: ${error}`;
    }
    // The module still answers after the error.
    const t = carom.sweep_ball_ball(ball(0, 1), {x: 4, y: 0}, ball(5, 1), {x: 0, y: 0}).t;
    return {message, t};
  });
  assert.match(outcome.message, /^carom::sweep_ball_ball: a\.radius = -1/);
  assert.equal(outcome.t, 0.75);  // the gap of 3 closes after 3/4 of the movement 4
  assert.deepEqual(problems, []);
  await page.close();
});

test('a lattice too dense for its box says why', async () => {
  const {page, problems} = await openPage(session, 'index.html');
  const message = await page.evaluate(async () => {
    const {carom} = await import('./js/carom.js');
    const world = new carom.DrawnWorld({boundary: carom.Boundary.box, lower: {x: 0, y: 0},
                                        upper: {x: 10, y: 10}, restitution: 1,
                                        collapse_time: 0, cell_size: 0,
                                        gravity: {x: 0, y: 0}, rest_height: 1e-3});
    try {
      world.fill_lattice({count: 100, packing_fraction: 0.9, speed: 1, seed: 1});
    } catch (error) {
      return error.message;
    } finally {
      world.delete();
    }
    return 'no error';
  });
  assert.match(message, /packing_fraction = 0\.9.*too dense/);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a table call refuses a bad strike, spin or world with carom\'s message, and a copy goes ' +
     'on by itself', async () => {
  const {page, problems} = await openPage(session, 'index.html');
  const outcome = await page.evaluate(async () => {
    const {carom} = await import('./js/carom.js');
    // The table without its break shot, which step would strike at time 0.
    const scene = await (await fetch('examples/billiards.json')).json();
    delete scene.shots;
    const table = carom.load_scene(JSON.stringify(scene), 'billiards.json');
    const plain = new carom.DrawnWorld({boundary: carom.Boundary.box, lower: {x: 0, y: 0},
                                        upper: {x: 10, y: 10}, restitution: 1,
                                        collapse_time: 0, cell_size: 0,
                                        gravity: {x: 0, y: 0}, rest_height: 1e-3});
    plain.add_ball({x: 5, y: 5}, {x: 0, y: 0}, 1, 1);
    const refusal = (call) => {
      try {
        call();
      } catch (error) {
        return error instanceof Error ? error.message : `not an Error: ${error}`;
      }
      return 'no error';
    };
    const out = {
      noSpeed: refusal(() => table.strike(0, {direction: 1})),
      textSpeed: refusal(() => table.strike(0, {speed: 'fast'})),
      notObject: refusal(() => table.strike(0, 3)),
      farTip: refusal(() => table.strike(0, {speed: 1, side: 0.03})),
      badSpin: refusal(() => table.set_spin(0, {x: 'a'})),
      noBall: refusal(() => table.motion_state(99)),
      noTable: refusal(() => plain.strike(0, {speed: 1})),
      plainTable: plain.table(),
      cloth: table.table().sliding_friction,
      state: table.motion_state(0),
    };
    // A copy struck and run to rest leaves the original as it was.
    const copy = table.copy();
    copy.strike(0, {speed: 0.3, direction: Math.PI / 2});
    copy.step(30);
    out.copyRests = copy.at_rest();
    out.copyMoved = copy.position(0).y > table.position(0).y + 0.1;
    out.originalState = table.motion_state(0);
    out.originalTime = table.time();
    copy.delete();
    table.delete();
    plain.delete();
    return out;
  });
  assert.match(outcome.noSpeed, /^carom::DrawnWorld::strike: speed = absent/);
  assert.match(outcome.textSpeed, /^carom::DrawnWorld::strike: speed = fast: must be a number/);
  assert.match(outcome.notObject, /^carom::DrawnWorld::strike: cue = /);
  assert.match(outcome.farTip, /^carom::World::strike: .*side/);
  assert.match(outcome.badSpin, /^carom::DrawnWorld::set_spin: x = a: must be a number/);
  assert.match(outcome.noBall, /index = 99/);
  assert.match(outcome.noTable, /^carom::World::strike: .*table/);
  assert.equal(outcome.plainTable, null);
  assert.equal(outcome.cloth, 0.2);
  assert.equal(outcome.state, 'stationary');
  assert.ok(outcome.copyRests && outcome.copyMoved);
  assert.equal(outcome.originalState, 'stationary');
  assert.equal(outcome.originalTime, 0);
  assert.deepEqual(problems, []);
  await page.close();
});
