// "Many balls" with scene files: every example in examples/ from the menu, a file dropped on the
// page or chosen with the file picker, read by carom's own scene library compiled to wasm. A
// malformed file shows the library's message (file:line:column) on the page and changes nothing;
// pockets swallow balls; an elastic example keeps its energy.
import assert from 'node:assert/strict';
import {readdir, readFile} from 'node:fs/promises';
import {resolve} from 'node:path';
import {after, before, test} from 'node:test';

import {OUTPUT, REPO, openBrowser, openPage, readout} from './browser.mjs';

// 10⁵ disks (periodic-gas) are generated and checked in the page; a loaded machine is slow.
const LOAD_TIMEOUT_MS = 90000;
const RUN_TIMEOUT_MS = 120000;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

const EXAMPLES = resolve(REPO, 'examples');
const exampleNames = (await readdir(EXAMPLES)).filter((name) => name.endsWith('.json')).sort();

// The balls a scene holds, counted from the JSON itself: the explicit ones and every generator's
// count (pockets are not balls).
function ballsIn(scene) {
  return (scene.balls ?? []).length +
         (scene.generators ?? []).reduce((sum, generator) => sum + generator.count, 0);
}

async function waitForScene(page, id, timeout = LOAD_TIMEOUT_MS) {
  await page.waitForFunction((want) => document.body.dataset.scene === want, id,
                             {timeout, polling: 100});
}

const sceneError = async (page) => (await page.textContent('#scene-error')).trim();

// A drop of a file with this name and text on the page, as a browser makes it.
async function dropFile(page, name, text) {
  await page.evaluate(({name, text}) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([text], name, {type: 'application/json'}));
    document.getElementById('box').dispatchEvent(
        new DragEvent('drop', {dataTransfer: transfer, bubbles: true, cancelable: true}));
  }, {name, text});
}

test('the menu lists every example in examples/', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
  const listed = await page.$$eval('#scene option', (options) => options.map((o) => o.value));
  for (const name of exampleNames) assert.ok(listed.includes(`example:${name}`), name);
  assert.deepEqual(problems, []);
  await page.close();
});

for (const name of exampleNames) {
  test(`example ${name}: loaded from the menu with all its balls`,
       {timeout: LOAD_TIMEOUT_MS + 20000}, async () => {
    const scene = JSON.parse(await readFile(resolve(EXAMPLES, name), 'utf8'));
    const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
    await page.selectOption('#scene', `example:${name}`);
    await waitForScene(page, `example:${name}`);
    assert.equal(await readout(page, 'balls'), String(ballsIn(scene)));
    assert.equal(await sceneError(page), '');
    // The view is the scene's box or cell when it has one.
    const view = await page.evaluate(() => window.caromPlayground.view);
    if (scene.world?.boundary === 'box' || scene.world?.boundary === 'periodic') {
      assert.deepEqual([view.x, view.y, view.x + view.width, view.y + view.height],
                       [...scene.world.lower, ...scene.world.upper]);
    }
    // A few frames run without an error, then the picture is kept for a look.
    await page.click('#step');
    await page.click('#step');
    await page.screenshot({path: `${OUTPUT}/scene-${name.replace('.json', '')}.png`});
    assert.deepEqual(problems, []);
    await page.close();
  });
}

const POCKET_SCENE = `{
  "carom_scene": 1,
  "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
  "balls": [
    {"name": "cue", "position": [5, 5], "velocity": [6, 0], "radius": 0.5, "color": "white"},
    {"position": [5, 8], "velocity": [0, 0], "radius": 0.5, "color": "#c03030"}
  ],
  "pockets": [{"name": "side", "position": [16, 5], "radius": 1}]
}
`;

test('a dropped scene file loads, and its pocket swallows the ball that reaches it',
     {timeout: RUN_TIMEOUT_MS}, async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
  await dropFile(page, 'pocket.json', POCKET_SCENE);
  await waitForScene(page, 'file:pocket.json');
  assert.equal(await page.inputValue('#scene'), 'file:pocket.json');
  assert.equal(await readout(page, 'balls'), '2');
  // The cue ball's surface reaches the pocket's at x = 16 − 1 − 0.5 = 14.5, after 9.5/6 ≈ 1.58
  // time units; 2 time units (120 frames) are past that, and the other ball never moves.
  for (let frame = 0; frame < 120; ++frame) await page.click('#step');
  assert.equal(await readout(page, 'balls'), '1');
  // Kinetic energy left: the ball at rest.
  assert.equal(Number(await readout(page, 'energy')), 0);
  assert.deepEqual(problems, []);
  await page.close();
});

// Scene files are drawn y up: a ball is found, and dragged, where it is drawn.
test('a ball of a scene file is dragged where the mouse takes it (y up)', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
  await dropFile(page, 'pocket.json', POCKET_SCENE);
  await waitForScene(page, 'file:pocket.json');
  const onScreen = (p) => page.evaluate((q) => {
    const {view} = window.caromPlayground;
    const box = document.getElementById('box').getBoundingClientRect();
    return {x: box.left + (q.x - view.x) / view.width * box.width,
            y: box.top + (view.y + view.height - q.y) / view.height * box.height};
  }, p);
  // The red ball at (5, 8), in the upper part of the picture, to (8, 8): nothing in the way.
  const from = await onScreen({x: 5, y: 8});
  const to = await onScreen({x: 8, y: 8});
  assert.ok(from.y < (await onScreen({x: 5, y: 5})).y, 'y = 8 is drawn above y = 5');
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, {steps: 5});
  await page.mouse.up();
  const moved = await page.evaluate(() => window.caromPlayground.world.position(1));
  // A pixel is 20/800 of a length unit here; 0.1 allows a few.
  assert.ok(Math.abs(moved.x - 8) < 0.1 && Math.abs(moved.y - 8) < 0.1,
            `at (${moved.x}, ${moved.y})`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a scene file chosen with the file picker loads', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
  await page.setInputFiles('#scene-file', {name: 'cradle.json', mimeType: 'application/json',
    buffer: await readFile(resolve(EXAMPLES, 'newtons-cradle.json'))});
  await waitForScene(page, 'file:cradle.json');
  assert.equal(await readout(page, 'balls'), '6');
  assert.deepEqual(problems, []);
  await page.close();
});

// A radius of -2 on line 4. The native `carom info` says of the same text
// "FILE:4:44: balls[0].radius = -2: must be > 0"; the page must show the same.
const BAD_FIELD = `{
  "carom_scene": 1,
  "world": {"boundary": "box", "lower": [0, 0], "upper": [20, 10]},
  "balls": [{"position": [5, 5], "radius": -2}]
}
`;
const BAD_SYNTAX = '{\n  "carom_scene": 1,\n  "balls": [\n}\n';

test('a malformed scene file shows the scene library\'s message on the page', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?paused=1');
  const ballsBefore = await readout(page, 'balls');
  await page.setInputFiles('#scene-file', {name: 'bad-radius.json', mimeType: 'application/json',
                                           buffer: Buffer.from(BAD_FIELD)});
  await page.waitForFunction(() => document.getElementById('scene-error').textContent !== '');
  const message = await sceneError(page);
  assert.equal(message, 'bad-radius.json:4:44: balls[0].radius = -2: must be > 0');
  // Nothing else changed: the previous world stays, the menu keeps its choice.
  assert.equal(await readout(page, 'balls'), ballsBefore);
  assert.equal(await page.inputValue('#scene'), 'box');

  await dropFile(page, 'broken.json', BAD_SYNTAX);
  await page.waitForFunction(() => /^broken\.json:/.test(
      document.getElementById('scene-error').textContent));
  assert.match(await sceneError(page), /^broken\.json:4:1: /);
  // A good file afterwards clears the message.
  await dropFile(page, 'pocket.json', POCKET_SCENE);
  await waitForScene(page, 'file:pocket.json');
  assert.equal(await sceneError(page), '');
  // Shown on the page, not raised: no console error, no uncaught exception.
  assert.deepEqual(problems, []);
  await page.close();
});

async function waitForTime(page, time) {
  await page.waitForFunction(
      (t) => Number(document.querySelector('[data-readout="time"]').textContent) >= t, time,
      {timeout: RUN_TIMEOUT_MS, polling: 100});
}

test('box-of-1000 (elastic): the energy stays constant over 5 time units',
     {timeout: RUN_TIMEOUT_MS + 20000}, async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?scene=example:box-of-1000.json');
  await waitForScene(page, 'example:box-of-1000.json');
  const energyAtStart = await readout(page, 'energy');
  await waitForTime(page, 5);
  assert.ok(Number(await readout(page, 'collisions')) > 1000, 'the balls collide');
  // Ten significant digits shown; carom conserves energy to rounding (~10⁻¹³ relative).
  assert.equal(await readout(page, 'energy'), energyAtStart);
  assert.deepEqual(problems, []);
  await page.close();
});
