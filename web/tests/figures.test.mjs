// The figures of "Two moving balls" and "Walls and arcs" as a reader sees them: y points up;
// A and B have the colours of `carom sweep --svg` and of examples/two-moving-balls.json; a
// legend in two parts (the step, the bounce) names every mark in the figure's own colours; no
// label lies under a drag handle; and after a drag the view refits so that every arrow, the
// movements after the bounce included, is in sight.
import assert from 'node:assert/strict';
import {execFileSync} from 'node:child_process';
import {mkdtemp, readFile, rm} from 'node:fs/promises';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {after, before, test} from 'node:test';

import {CAROM_CLI, OUTPUT, REPO, openBrowser, openPage, readout} from './browser.mjs';
import {figurePoint, mouseDrag} from './drag.mjs';

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

// The centre of a handle on the screen.
async function handleCentre(page, name) {
  const box = await page.locator(`[data-handle="${name}"]`).boundingBox();
  return {x: box.x + box.width / 2, y: box.y + box.height / 2};
}

const numbers = (text) => text.match(/-?[\d.]+(e[+-]?\d+)?/g).map(Number);

for (const [path, handle, key] of [['two-balls.html', 'a', 'a'], ['walls.html', 'ball', 'ball']]) {
  test(`${path}: a ball dragged up on the screen gets a larger y`, async () => {
    const {page, problems} = await openPage(session, path);
    const [x0, y0] = numbers(await readout(page, key));
    const from = await handleCentre(page, handle);
    await mouseDrag(page, from, {x: from.x, y: from.y - 80});
    const [x1, y1] = numbers(await readout(page, key));
    assert.equal(x1, x0);
    assert.ok(y1 > y0 + 1, `y went from ${y0} to ${y1}`);
    assert.deepEqual(problems, []);
    await page.close();
  });
}

test('two-balls.html: B, at the larger y, is drawn above A', async () => {
  const {page, problems} = await openPage(session, 'two-balls.html');
  // A starts at (0, 0), B at (8, 3).
  const a = await handleCentre(page, 'a');
  const b = await handleCentre(page, 'b');
  assert.ok(b.y < a.y, `B at screen y ${b.y}, A at ${a.y}`);
  assert.ok(b.x > a.x);
  assert.deepEqual(problems, []);
  await page.close();
});

// '#rrggbb' of a CSS colour as getComputedStyle gives it ('rgb(214, 39, 40)').
function hex(css) {
  const [r, g, b] = css.match(/\d+/g).map(Number);
  return '#' + [r, g, b].map((c) => c.toString(16).padStart(2, '0')).join('');
}

test('A and B have one colour each: on the page, in carom sweep --svg, in the example',
     async () => {
  const {page, problems} = await openPage(session, 'two-balls.html');
  const drawn = await page.evaluate(() => {
    const style = (selector) => getComputedStyle(document.querySelector(selector));
    const ball = (cls) => style(`#figure circle.ball.${cls}:not(.ghost):not(.outline)`);
    return {a: {stroke: ball('a').stroke, fill: ball('a').fill},
            b: {stroke: ball('b').stroke, fill: ball('b').fill}};
  });
  // The sweep picture of the page's own case draws A's disc, then B's, first.
  const dir = await mkdtemp(join(tmpdir(), 'carom-sweep-'));
  try {
    execFileSync(CAROM_CLI, ['sweep', '--a', '0,0,1', '--va', '6,2', '--b', '8,3,1.5', '--vb',
                             '-4,-1', '--svg', join(dir, 'two.svg')]);
    const svg = await readFile(join(dir, 'two.svg'), 'utf8');
    const circles = svg.match(/<circle [^>]*>/g).slice(0, 2).map((c) => ({
      fill: c.match(/fill="(#[0-9a-f]{6})"/)[1], stroke: c.match(/stroke="(#[0-9a-f]{6})"/)[1]}));
    const scene = JSON.parse(await readFile(resolve(REPO, 'examples/two-moving-balls.json'),
                                            'utf8'));
    const colourOf = (name) => scene.balls.find((b) => b.name === name).color.toLowerCase();
    for (const [i, name] of [[0, 'a'], [1, 'b']]) {
      assert.equal(hex(drawn[name].stroke), circles[i].stroke, `${name}: page and sweep`);
      assert.equal(hex(drawn[name].fill), circles[i].fill, `${name}: the pale fills`);
      assert.equal(colourOf(name.toUpperCase()), circles[i].stroke, `${name}: the example`);
    }
    assert.notEqual(circles[0].stroke, circles[1].stroke);
  } finally {
    await rm(dir, {recursive: true, force: true});
  }
  assert.deepEqual(problems, []);
  await page.close();
});

// Every legend entry against the figure: the mark's colours are those of a shape the figure
// draws with the same classes.
async function legendAgainstFigure(page) {
  return page.evaluate(() => {
    const paint = (node) => {
      const style = getComputedStyle(node);
      return `stroke ${style.stroke}, fill ${style.fill}, dashes ${style.strokeDasharray}`;
    };
    const entries = [];
    // The figure's shape of exactly these classes (an arrow's: its shaft).
    const shapes = [...document.querySelectorAll('#figure .world *')];
    for (const item of document.querySelectorAll('#legend li')) {
      const [mark, ...rest] = item.dataset.mark.split(' ');
      const classes = (mark === 'arrow' ? ['arrow', ...rest] : rest).join(' ');
      const found = shapes.find((node) => node.getAttribute('class') === classes);
      const inFigure = mark === 'arrow' ? found?.querySelector('line') : found;
      const inLegend = item.querySelector(mark === 'arrow' ? 'line' : 'circle, line');
      entries.push({text: item.textContent, legend: paint(inLegend),
                    figure: inFigure ? paint(inFigure) : 'not drawn'});
    }
    const titles = [...document.querySelectorAll('#legend h3')].map((h) => h.textContent);
    return {titles, entries};
  });
}

for (const [path, wanted] of [
  ['two-balls.html', ["va: A's movement during the step",
                      "v3 = va − vb: A's movement seen from B", 'the line of centres',
                      "va′: A's movement after the bounce", "vb′: B's movement after the bounce"]],
  ['walls.html', ['v: its movement during the step', 'the first one the ball touches',
                  'v along the normal', "v′: the ball's movement after the bounce"]],
]) {
  test(`${path}: a legend in two parts, each mark in the colours of the figure`, async () => {
    const {page, problems} = await openPage(session, path);
    const {titles, entries} = await legendAgainstFigure(page);
    assert.deepEqual(titles, ['The step', 'The bounce']);
    const texts = entries.map((e) => e.text);
    for (const text of wanted) assert.ok(texts.includes(text), text);
    for (const e of entries) assert.equal(e.legend, e.figure, e.text);
    assert.deepEqual(problems, []);
    await page.close();
  });
}

// Pairs of a label and a (non-ball) handle whose boxes on the screen meet.
async function labelsUnderHandles(page) {
  return page.evaluate(() => {
    const hits = [];
    const handles = [...document.querySelectorAll('#figure circle.handle:not(.ball-handle)')];
    for (const label of document.querySelectorAll('#figure text.label')) {
      const box = label.getBoundingClientRect();
      for (const handle of handles) {
        const c = handle.getBoundingClientRect();
        const r = c.width / 2;
        const x = c.x + r;
        const y = c.y + r;
        const dx = Math.max(box.left - x, 0, x - box.right);
        const dy = Math.max(box.top - y, 0, y - box.bottom);
        if (dx * dx + dy * dy < r * r) {
          hits.push(`${label.textContent} under ${handle.dataset.handle}`);
        }
      }
    }
    return hits;
  });
}

// Every arrow (and label) of the figure, on the screen, inside the figure's box.
async function outOfSight(page) {
  return page.evaluate(() => {
    const frame = document.getElementById('figure').getBoundingClientRect();
    const out = [];
    for (const node of document.querySelectorAll('#figure g.arrow, #figure text.label')) {
      const box = node.getBoundingClientRect();
      if (box.width === 0 && box.height === 0) continue;  // a zero arrow draws nothing
      if (box.left < frame.left - 1 || box.right > frame.right + 1 || box.top < frame.top - 1 ||
          box.bottom > frame.bottom + 1) {
        out.push(`${node.getAttribute('class')} ${node.textContent}`.trim());
      }
    }
    return out;
  });
}

const arrowCount = (page) => page.$$eval('#figure g.arrow line', (lines) => lines.length);

for (const [path, drags, names, arrows] of [
  // A's movement made long, towards the upper right, past where the first view ends; then B's.
  // The balls still meet, so the movements after the bounce are drawn, long too.
  ['two-balls.html', [[{x: 6, y: 2}, {x: 24, y: 15}], [{x: 4, y: 2}, {x: -12, y: -9}]],
   ['va', 'vb', 'v3', 'va′', 'vb′'], 9],
  // The ball's movement made long: it bounces off segment 1 and leaves far to the left; then
  // upwards: it bounces off segment 2 and leaves far down.
  ['walls.html', [[{x: 9, y: 1}, {x: 30, y: 1}], [{x: 30, y: 1}, {x: 4, y: 25}]], ['v', 'v′'],
   3],
]) {
  test(`${path}: after each drag every arrow is in sight, no label under a handle`, async () => {
    const {page, problems} = await openPage(session, path);
    assert.deepEqual(await labelsUnderHandles(page), []);
    const before = await page.getAttribute('#figure', 'data-view');
    for (const [from, to] of drags) {
      // The far end is outside the figure on the screen: the drag carries on beyond it.
      await mouseDrag(page, await figurePoint(page, from), await figurePoint(page, to));
      assert.deepEqual(await outOfSight(page), [], `after the drag to (${to.x}, ${to.y})`);
      assert.deepEqual(await labelsUnderHandles(page), []);
    }
    assert.notEqual(await page.getAttribute('#figure', 'data-view'), before, 'the view refitted');
    const labels = await page.$$eval('#figure text.label',
                                     (nodes) => nodes.map((n) => n.textContent));
    assert.deepEqual(labels.sort(), names.sort());
    assert.ok(await arrowCount(page) >= arrows);
    await page.screenshot({path: `${OUTPUT}/${path.replace('.html', '')}-refitted.png`});
    assert.deepEqual(problems, []);
    await page.close();
  });
}
