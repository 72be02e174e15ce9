// Bad arguments: the library's carom::InvalidArgument reaches JavaScript as an Error carrying the
// library's own message (web/bindings/js_error.hpp), and the module keeps working afterwards.
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
