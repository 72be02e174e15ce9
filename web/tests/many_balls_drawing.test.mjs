// "Many balls" as drawn: y up in the page's own boxes too; an open world's balls stay in view
// as they fly apart; the speed colours have a legend that matches the pixels; disc edges are
// anti-aliased; the "Check overlaps" answer goes when the scene changes; the front page's count
// of balls is the page's.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage, readout} from './browser.mjs';

// At 60 frames a second 5 time units take 5 s; a loaded machine may give fewer frames.
const RUN_TIMEOUT_MS = 120000;

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

async function waitForScene(page, id) {
  await page.waitForFunction((want) => document.body.dataset.scene === want, id,
                             {timeout: 60000, polling: 100});
}

// Ball i: where it is and how big, on the screen (CSS pixels) and on the canvas (its pixels),
// with y up: the view's top edge at the canvas's top.
async function ballDrawn(page, i) {
  return page.evaluate((index) => {
    const {world, view} = window.caromPlayground;
    const canvas = document.getElementById('box');
    const box = canvas.getBoundingClientRect();
    const p = world.position(index);
    const radius = world.snapshot()[4 * index + 2];
    const across = (p.x - view.x) / view.width;
    const down = (view.y + view.height - p.y) / view.height;
    return {world: p, radius,
            screen: {x: box.left + across * box.width, y: box.top + down * box.height},
            canvas: {x: across * canvas.width, y: down * canvas.height},
            pixelsPerUnit: canvas.width / view.width};
  }, i);
}

// The canvas's pixel at (x, y) (its own pixels) as '#rrggbb'.
async function pixel(page, at) {
  return page.evaluate(({x, y}) => {
    const context = document.getElementById('box').getContext('2d');
    const [r, g, b] = context.getImageData(Math.floor(x), Math.floor(y), 1, 1).data;
    return '#' + [r, g, b].map((c) => c.toString(16).padStart(2, '0')).join('');
  }, at);
}

test('a ball of the page\'s own box dragged up on the screen gets a larger y', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=10&paused=1');
  const ball = await ballDrawn(page, 0);
  await page.mouse.move(ball.screen.x, ball.screen.y);
  await page.mouse.down();
  await page.mouse.move(ball.screen.x, ball.screen.y - 30, {steps: 5});
  await page.mouse.up();
  const moved = await page.evaluate(() => window.caromPlayground.world.position(0));
  assert.ok(moved.y > ball.world.y + 1, `y went from ${ball.world.y} to ${moved.y}`);
  assert.ok(Math.abs(moved.x - ball.world.x) < 1);
  assert.deepEqual(problems, []);
  await page.close();
});

test('an open world\'s balls stay in view as they fly apart', {timeout: RUN_TIMEOUT_MS},
     async () => {
  const {page, problems} = await openPage(session,
                                          'many-balls.html?scene=example:two-moving-balls.json');
  await waitForScene(page, 'example:two-moving-balls.json');
  const first = await page.evaluate(() => ({...window.caromPlayground.view}));
  // After the contact at t = 0.58 they part at about 4 and 6 length units per time unit: by
  // t = 5 each is far outside the first view (about 12 × 6 units).
  await page.waitForFunction(() => Number(document.querySelector('[data-readout="time"]')
                                              .textContent) >= 5,
                             undefined, {timeout: RUN_TIMEOUT_MS, polling: 100});
  await page.click('#pause');
  const view = await page.evaluate(() => ({...window.caromPlayground.view}));
  assert.notDeepEqual(view, first, 'the view moved');
  // The canvas keeps its shape.
  assert.ok(Math.abs(view.width / view.height - first.width / first.height) < 1e-9);
  for (const [i, colour] of [[0, '#d62728'], [1, '#1f6fb4']]) {
    const ball = await ballDrawn(page, i);
    const {x, y} = ball.world;
    assert.ok(x - ball.radius >= view.x && x + ball.radius <= view.x + view.width &&
              y - ball.radius >= view.y && y + ball.radius <= view.y + view.height,
              `ball ${i} at (${x}, ${y}) in the view ${JSON.stringify(view)}`);
    // And drawn there, in the scene's colour (A red, B blue).
    assert.equal(await pixel(page, ball.canvas), colour, `ball ${i}`);
  }
  await page.screenshot({path: `${OUTPUT}/many-balls-open-world-followed.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('the speed legend gives each colour\'s speeds, and the balls are drawn so', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=300&paused=1');
  const legend = () => page.$$eval('#speed-legend > span', (items) => items.map((item) => ({
    colour: item.dataset.colour, from: Number(item.dataset.from), to: Number(item.dataset.to),
    text: item.textContent})));
  assert.equal(await page.isVisible('#speed-legend'), true);
  // Every ball starts at speed 10; the scale's top is twice that, in five bands.
  let bands = await legend();
  assert.deepEqual(bands.map((b) => b.text), ['0 to 4', '4 to 8', '8 to 12', '12 to 16',
                                               '16 or more']);
  const bandOf = (speed) => bands.find((b) => speed >= b.from && speed < b.to);
  for (const i of [0, 137, 299]) {
    const ball = await ballDrawn(page, i);
    assert.equal(await pixel(page, ball.canvas), bandOf(10).colour, `ball ${i}`);
  }
  // The speed slider at 40: every ball four times faster, the bands four times wider.
  await page.evaluate(() => {
    const input = document.getElementById('speed');
    input.value = '40';
    input.dispatchEvent(new Event('input', {bubbles: true}));
  });
  bands = await legend();
  assert.equal(bands[4].text, '64 or more');
  await page.click('#step');
  assert.equal(await pixel(page, (await ballDrawn(page, 0)).canvas), bandOf(40).colour);
  // A scene that colours every ball needs no speed legend.
  await page.selectOption('#scene', 'example:two-moving-balls.json');
  await waitForScene(page, 'example:two-moving-balls.json');
  assert.equal(await page.isVisible('#speed-legend'), false);
  assert.deepEqual(problems, []);
  await page.close();
});

test('disc edges are anti-aliased: pixels between the ball\'s and the background\'s colour',
     async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=10&paused=1');
  const ball = await ballDrawn(page, 0);
  const r = ball.radius * ball.pixelsPerUnit;
  assert.ok(r > 10, `a radius of ${r} pixels`);
  const inside = await pixel(page, ball.canvas);
  const outside = '#fafafa';
  // Along the row through the centre, across the right edge.
  const edge = [];
  for (let dx = Math.floor(r) - 3; dx <= Math.ceil(r) + 3; ++dx) {
    edge.push(await pixel(page, {x: ball.canvas.x + dx, y: ball.canvas.y}));
  }
  const channels = (hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
  const between = edge.filter((p) => p !== inside && p !== outside).filter((p) => {
    const [a, b, c] = [channels(inside), channels(outside), channels(p)];
    return c.every((v, k) => v >= Math.min(a[k], b[k]) && v <= Math.max(a[k], b[k]));
  });
  assert.ok(between.length >= 1, `edge pixels ${edge.join(' ')}`);
  assert.equal(edge[0], inside);
  assert.equal(edge[edge.length - 1], outside);
  assert.deepEqual(problems, []);
  await page.close();
});

test('the "Check overlaps" answer is cleared when the scene changes', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=100&paused=1');
  await page.click('#check');
  assert.match(await page.textContent('#audit'), /^No two balls overlap/);
  await page.selectOption('#scene', 'obstacles');
  await waitForScene(page, 'obstacles');
  assert.equal(await page.textContent('#audit'), '');
  // And on Reset, which builds the scene again.
  await page.click('#check');
  assert.notEqual(await page.textContent('#audit'), '');
  await page.click('#reset');
  await page.waitForFunction(() => document.getElementById('audit').textContent === '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('the front page\'s largest number of balls is the page\'s', async () => {
  const {page, problems} = await openPage(session, 'many-balls.html?n=1000000&paused=1');
  // ?n= beyond the largest count takes the largest.
  const most = Number(await page.textContent('#count-out'));
  assert.equal(await readout(page, 'balls'), String(most));
  const front = await openPage(session, 'index.html');
  const said = (await front.page.textContent('ul.pages')).match(/up to ([\d ]+) balls/)[1];
  assert.equal(Number(said.replace(/ /g, '')), most);
  assert.deepEqual([...problems, ...front.problems], []);
  await front.page.close();
  await page.close();
});
