// "Two moving balls": drag ball A (with the mouse) and the end of B's movement (with a finger),
// then check the t, the positions at contact and the movements after the bounce that the page
// shows against what `carom sweep --json` prints for the same case, to the digits shown.
import assert from 'node:assert/strict';
import {execFileSync} from 'node:child_process';
import {after, before, test} from 'node:test';

import {CAROM_CLI, OUTPUT, openBrowser, openPage, openTouchPage, readout} from './browser.mjs';
import {figurePoint, mouseDrag, sameDigits, touchDrag} from './drag.mjs';

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

// The page's case as `carom sweep` options, read from the page's own readout of its inputs.
async function pageCase(page) {
  const numbers = async (key) => (await readout(page, key)).match(/-?[\d.e+-]+/g).map(Number);
  const [ax, ay, ar] = await numbers('a');
  const [bx, by, br] = await numbers('b');
  return {a: [ax, ay, ar], va: await numbers('va'), b: [bx, by, br], vb: await numbers('vb')};
}

function cliSweep(c, extra = []) {
  const out = execFileSync(CAROM_CLI, ['sweep', '--a', c.a.join(','), '--va', c.va.join(','),
                                       '--b', c.b.join(','), '--vb', c.vb.join(','), '--json',
                                       ...extra]);
  return JSON.parse(out);
}

async function mouseDragWorld(page, from, to) {
  await mouseDrag(page, await figurePoint(page, from), await figurePoint(page, to));
}

function assertVector(shown, expected, what) {
  const parts = shown.match(/-?[\d.e+-]+/g);
  assert.equal(parts.length, 2, `${what}: ${shown}`);
  parts.forEach((part, i) => {
    assert.ok(sameDigits(part, expected[i]), `${what}: page ${shown}, carom sweep ${expected}`);
  });
}

async function checkAgainstCli(page, extra = []) {
  const c = await pageCase(page);
  const cli = cliSweep(c, extra);
  const t = await readout(page, 't');
  if (!cli.hit) {
    assert.match(t, /no contact/, `carom sweep says no contact, the page says ${t}`);
    return cli;
  }
  assert.ok(sameDigits(t, cli.t), `page t = ${t}, carom sweep t = ${cli.t}`);
  assertVector(await readout(page, 'a_at'), cli.a_at, 'A at contact');
  assertVector(await readout(page, 'b_at'), cli.b_at, 'B at contact');
  assertVector(await readout(page, 'va_after'), cli.va_after, 'A after');
  assertVector(await readout(page, 'vb_after'), cli.vb_after, 'B after');
  return cli;
}

async function setSlider(page, id, value) {
  await page.evaluate(({id, value}) => {
    const input = document.getElementById(id);
    input.value = String(value);
    input.dispatchEvent(new Event('input', {bubbles: true}));
  }, {id, value});
}

test('dragging ball A gives the t that carom sweep prints for the same case', async () => {
  const {page, problems} = await openPage(session, 'two-balls.html');
  // The default case first, then A dragged to three places: two contacts and a miss.
  const cases = [null, {x: 1.5, y: -1.2}, {x: -2.3, y: 1.4}, {x: 0.7, y: -4.1}];
  let from = {x: 0, y: 0};
  const hits = [];
  for (const target of cases) {
    if (target) {
      await mouseDragWorld(page, from, target);
      const shownA = await readout(page, 'a');
      assert.equal(shownA, `(${target.x}, ${target.y}), r 1`, 'A went where it was dragged');
      from = target;
    }
    hits.push((await checkAgainstCli(page)).hit);
  }
  // The cases are chosen so that both kinds occur: a test that never saw a miss (or a hit)
  // would prove less than it claims.
  assert.deepEqual(hits, [true, true, true, false]);
  await page.screenshot({path: `${OUTPUT}/two-balls-dragged.png`});
  assert.deepEqual(problems, []);
  await page.close();
});

test('masses and restitution from the sliders reach the bounce', async () => {
  const {page, problems} = await openPage(session, 'two-balls.html');
  await setSlider(page, 'mass-a', 2.5);
  await setSlider(page, 'mass-b', 0.4);
  await setSlider(page, 'restitution', 0.65);
  const cli = await checkAgainstCli(page, ['--ma', '2.5', '--mb', '0.4', '--e', '0.65']);
  assert.ok(cli.hit);
  // The equal-mass elastic answer differs: the sliders really changed the bounce.
  const plain = cliSweep(await pageCase(page));
  assert.notDeepEqual(cli.va_after, plain.va_after);
  assert.deepEqual(problems, []);
  await page.close();
});

test('a touch drag moves the end of B\'s movement', async () => {
  const {context, page, problems} = await openTouchPage(session, 'two-balls.html');
  // B starts at (8, 3) moving by (-4, -1): the end handle is at (4, 2).
  await touchDrag(page, await figurePoint(page, {x: 4, y: 2}),
                  await figurePoint(page, {x: 3, y: 0.5}));
  assert.equal(await readout(page, 'vb'), '(-5, -2.5)');
  await checkAgainstCli(page);
  await page.screenshot({path: `${OUTPUT}/two-balls-touch.png`, fullPage: true});
  assert.deepEqual(problems, []);
  await context.close();
});
