// "Many balls": 10 time units of the box, read from the page's own readout: energy stays put for
// e = 1 and drops for e < 1, the collision count grows; dragging a ball (mouse and touch) never
// makes it overlap another ball or leave the box.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage, openTouchPage, readout} from './browser.mjs';
import {touchDrag} from './drag.mjs';

// At 60 frames a second 10 time units take 10 s; a loaded machine may give fewer frames.
const RUN_TIMEOUT_MS = 120000;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

async function waitForTime(page, time) {
  await page.waitForFunction(
      (t) => Number(document.querySelector('[data-readout="time"]').textContent) >= t, time,
      {timeout: RUN_TIMEOUT_MS, polling: 100});
}

const count = async (page) => Number(await readout(page, 'collisions'));

async function setSlider(page, id, value) {
  await page.evaluate(({id, value}) => {
    const input = document.getElementById(id);
    input.value = String(value);
    input.dispatchEvent(new Event('input', {bubbles: true}));
  }, {id, value});
}

test('e = 1: over 10 time units the energy stays constant and collisions keep coming',
     {timeout: RUN_TIMEOUT_MS + 20000}, async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=300');
  assert.equal(await readout(page, 'balls'), '300');
  const energyAtStart = await readout(page, 'energy');
  // Every ball starts with speed 10 and mass 1: E = 300 · 10² / 2.
  assert.equal(Number(energyAtStart), 15000);
  await waitForTime(page, 5);
  const halfway = await count(page);
  await waitForTime(page, 10);
  const atEnd = await count(page);
  assert.ok(halfway > 0, 'collisions happen');
  assert.ok(atEnd > halfway, `the count grows: ${halfway} then ${atEnd}`);
  // Ten significant digits shown; the world conserves energy to rounding (~10⁻¹³ relative).
  assert.equal(await readout(page, 'energy'), energyAtStart);
  await page.screenshot({path: `${OUTPUT}/many-balls-10s.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('e = 0.5: the energy drops', {timeout: RUN_TIMEOUT_MS}, async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=300');
  await setSlider(page, 'restitution', 0.5);
  await page.waitForFunction(
      () => Number(document.querySelector('[data-readout="time"]').textContent) < 1);
  const energyAtStart = Number(await readout(page, 'energy'));
  await waitForTime(page, 3);
  const energy = Number(await readout(page, 'energy'));
  assert.ok(energy < 0.9 * energyAtStart, `energy ${energyAtStart} then ${energy}`);
  assert.ok(await count(page) > 0);
  assert.deepEqual(problems, []);
  await page.close();
});

// The ball's place on the screen: y up, the view's top edge at the canvas's top.
async function ballOnScreen(page, index) {
  return page.evaluate((i) => {
    const {world, view} = window.caromPlayground;
    const p = world.position(i);
    const box = document.getElementById('box').getBoundingClientRect();
    return {x: box.left + (p.x - view.x) / view.width * box.width,
            y: box.top + (view.y + view.height - p.y) / view.height * box.height};
  }, index);
}

const audit = (page) => page.evaluate(() => window.caromPlayground.world.audit());
const position = (page, i) => page.evaluate((j) => window.caromPlayground.world.position(j), i);

test('a dragged ball stops at the first ball or wall in its way', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=300&paused=1');
  const before = await position(page, 0);
  const start = await ballOnScreen(page, 0);
  const box = await page.evaluate(() => {
    const r = document.getElementById('box').getBoundingClientRect();
    return {right: r.right, bottom: r.bottom};
  });
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  // Through the crowd towards (and past) the far corner, checking after every move.
  const steps = 25;
  for (let i = 1; i <= steps; ++i) {
    await page.mouse.move(start.x + (box.right + 20 - start.x) * i / steps,
                          start.y + (box.bottom + 20 - start.y) * i / steps);
    assert.equal(await audit(page), '', `after move ${i}`);
  }
  await page.mouse.up();
  const moved = await position(page, 0);
  assert.ok(Math.hypot(moved.x - before.x, moved.y - before.y) > 1, 'the ball moved');
  await page.click('#check');
  assert.match(await page.textContent('#audit'), /^No two balls overlap/);
  await page.screenshot({path: `${OUTPUT}/many-balls-dragged.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('a ball can be dragged with a finger', async () => {
  const {context, page, problems} = await openTouchPage(session, 'many-balls.html?n=10&paused=1');
  const before = await position(page, 0);
  const start = await ballOnScreen(page, 0);
  await touchDrag(page, start, {x: start.x + 30, y: start.y + 30});
  const after = await position(page, 0);
  assert.ok(Math.hypot(after.x - before.x, after.y - before.y) > 1, 'the ball moved');
  assert.equal(await audit(page), '');
  assert.deepEqual(problems, []);
  await context.close();
});

test('the scene with walls and arcs runs, leaves no overlap and keeps its energy',
     {timeout: RUN_TIMEOUT_MS}, async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=1000');
  await page.selectOption('#scene', 'obstacles');
  await page.waitForFunction(
      () => Number(document.querySelector('[data-readout="time"]').textContent) < 1);
  // Lattice sites on a wall, a bumper or the cup stay empty.
  const balls = Number(await readout(page, 'balls'));
  assert.ok(balls > 800 && balls < 1000, `${balls} balls`);
  const energyAtStart = await readout(page, 'energy');
  assert.equal(Number(energyAtStart), balls * 10 * 10 / 2);
  await waitForTime(page, 3);
  assert.equal(await readout(page, 'energy'), energyAtStart);
  assert.ok(await count(page) > 0);
  assert.equal(await audit(page), '');
  await page.screenshot({path: `${OUTPUT}/many-balls-walls.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('pause, single step and the speed control', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=100');
  await page.click('#pause');
  const paused = Number(await readout(page, 'time'));
  await page.waitForTimeout(300);
  assert.equal(Number(await readout(page, 'time')), paused, 'paused: time stands still');
  for (let i = 0; i < 3; ++i) await page.click('#step');
  // Each step is one frame of 1/60 time unit; the time is shown to 3 decimals.
  assert.equal(await readout(page, 'time'), (paused + 3 / 60).toFixed(3));
  // Doubling every speed quadruples the kinetic energy (100 balls of mass 1 at speed 10 → 20).
  assert.equal(Number(await readout(page, 'energy')), 5000);
  await setSlider(page, 'speed', 20);
  await page.click('#step');
  assert.equal(Number(await readout(page, 'energy')), 20000);
  assert.deepEqual(problems, []);
  await page.close();
});
