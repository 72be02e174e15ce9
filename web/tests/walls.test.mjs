// "Walls and arcs": a ball dragged so that it meets a segment's end point, and so that it meets
// the arc from inside; the page's t, normal and bounce are checked against the closed forms
// worked out here by hand (circle against point, circle inside a circle).
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage, openTouchPage, readout} from './browser.mjs';
import {figurePoint, mouseDrag, sameDigits, touchDrag} from './drag.mjs';

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

async function drag(page, from, to) {
  await mouseDrag(page, await figurePoint(page, from), await figurePoint(page, to));
}

function assertVector(shown, expected, what) {
  const parts = shown.match(/-?[\d.e+-]+/g);
  assert.equal(parts.length, 2, `${what}: ${shown}`);
  parts.forEach((part, i) => {
    assert.ok(sameDigits(part, expected[i]), `${what}: page ${shown}, expected ${expected}`);
  });
}

// An elastic bounce off a static shape: the part of v along the unit normal n is reversed.
function reflect(v, n) {
  const along = v[0] * n[0] + v[1] * n[1];
  return [v[0] - 2 * along * n[0], v[1] - 2 * along * n[1]];
}

const RADIUS = 0.8;  // the ball's default radius

test('a ball passing just beyond a segment touches its end point', async () => {
  const {page, problems} = await openPage(session, 'walls.html');
  // The movement becomes (9, 0), then the ball starts at (0, 3.5): its centre passes 0.5 below
  // the end point (6, 3) of segment 1, closer than its radius.
  await drag(page, {x: 9, y: 1}, {x: 9, y: 0});
  await drag(page, {x: 0, y: 0}, {x: 0, y: 3.5});
  assert.equal(await readout(page, 'ball'), '(0, 3.5), r 0.8');
  assert.equal(await readout(page, 'move'), '(9, 0)');
  assert.equal(await readout(page, 'shape'), 'segment 1, at an end point');
  // At contact the centre is RADIUS from (6, 3): 0.5 below it and √(0.8² − 0.5²) before it.
  const before = Math.sqrt(RADIUS * RADIUS - 0.5 * 0.5);
  const t = (6 - before) / 9;
  assert.ok(sameDigits(await readout(page, 't'), t), `t ${await readout(page, 't')} vs ${t}`);
  const normal = [before / RADIUS, -0.5 / RADIUS];
  assertVector(await readout(page, 'normal'), normal, 'normal');
  assertVector(await readout(page, 'point'), [6, 3], 'contact point');
  assertVector(await readout(page, 'after'), reflect([9, 0], normal), 'after');
  await page.screenshot({path: `${OUTPUT}/walls-end-point.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('a ball inside the arc meets it from inside', async () => {
  const {page, problems} = await openPage(session, 'walls.html');
  // The movement becomes (6, 0), then the ball starts at (10, 0), 1 above the arc's centre
  // (10, 1), radius 3: it touches when its centre is 3 − 0.8 = 2.2 from the centre.
  await drag(page, {x: 9, y: 1}, {x: 6, y: 0});
  await drag(page, {x: 0, y: 0}, {x: 10, y: 0});
  assert.equal(await readout(page, 'shape'), 'arc 1');
  const reach = 3 - RADIUS;
  const dx = Math.sqrt(reach * reach - 1);
  assert.ok(sameDigits(await readout(page, 't'), dx / 6), `t ${await readout(page, 't')}`);
  const normal = [dx / reach, -1 / reach];
  assertVector(await readout(page, 'normal'), normal, 'normal');
  assertVector(await readout(page, 'point'), [10 + 3 * normal[0], 1 + 3 * normal[1]], 'point');
  assertVector(await readout(page, 'after'), reflect([6, 0], normal), 'after');
  await page.screenshot({path: `${OUTPUT}/walls-arc-inside.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('a touch drag moves a segment\'s end point', async () => {
  const {context, page, problems} = await openTouchPage(session, 'walls.html');
  await touchDrag(page, await figurePoint(page, {x: 6, y: -3}),
                  await figurePoint(page, {x: 7, y: -4}));
  assert.equal(await readout(page, 'segment0'), '(7, -4) to (6, 3)');
  assert.deepEqual(problems, []);
  await context.close();
});
