// "Compression": 100 disks of two sizes compressed at G = 0.01 jam amorphous at a packing
// fraction near 0.84, with the reduced pressure past the page's limit, a contact network near
// isostatic, the thermostat's temperature kept and the World's audit clean; disks of one size
// compressed alike crystallise; stopping the compression keeps the disks' size, and New start and
// the cell menu start again.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, eventually, openBrowser, openPage, readout} from './browser.mjs';

// A hundred disks jam after about 400 frames (7 s at 60 frames a second); a loaded machine gives
// fewer frames a second.
const JAM_TIMEOUT_MS = 120000;
const PRESSURE_LIMIT = 1e8;  // the page's

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

async function openJammed(query) {
  const opened = await openPage(session, `compress.html?${query}`);
  await opened.page.waitForFunction(() => window.caromCompression.jammed !== null, null,
                                    {timeout: JAM_TIMEOUT_MS, polling: 200});
  // The report after the jam.
  await opened.page.waitForFunction(
      () => document.getElementById('status').dataset.state === 'jammed', null,
      {timeout: JAM_TIMEOUT_MS, polling: 50});
  return opened;
}

// What the page shows and what the world holds, read in one go.
function state(page) {
  return page.evaluate(() => {
    const c = window.caromCompression;
    const w = c.world;
    const texts = Object.fromEntries([...document.querySelectorAll('[data-readout]')]
        .map((cell) => [cell.dataset.readout, cell.textContent.trim()]));
    return {
      texts,
      status: document.getElementById('status').dataset.state,
      button: {text: document.getElementById('compress').textContent,
               disabled: document.getElementById('compress').disabled},
      jammed: c.jammed,
      balls: w.ball_count(),
      eta: w.packing_fraction(),
      kineticPerDisk: w.kinetic_energy() / w.ball_count(),
      growth: w.growth_rate(),
      pairs: c.network.pairs.length / 2,
      rattlers: c.network.rattlers,
      meanContacts: c.network.mean_contacts_of_rest,
      psi6: w.psi6(),
      time: w.time(),
      audit: w.audit(),
      error: document.getElementById('error-line').textContent,
    };
  });
}

// The number a readout starts with ("3.93 (isostatic: 4)" gives 3.93).
function leading(text) {
  const value = Number(text.split(' ')[0]);
  assert.ok(Number.isFinite(value), `"${text}" does not start with a number`);
  return value;
}

test('two sizes compressed at G = 0.01 jam amorphous near η = 0.84, about isostatic',
     {timeout: JAM_TIMEOUT_MS + 30000}, async () => {
  const {page, problems} = await openJammed('n=100&mix=bi&rate=0.01&compress=1');
  const s = await state(page);
  await page.screenshot({path: `${OUTPUT}/compress-jammed.png`, fullPage: true});
  assert.equal(s.error, '');
  assert.equal(s.status, 'jammed');
  assert.deepEqual(s.button, {text: 'Jammed', disabled: true});
  assert.equal(s.balls, 100);
  assert.equal(s.jammed.stalled || s.jammed.pressure >= PRESSURE_LIMIT, true);
  assert.equal(s.growth, 0);
  // Random close packing of this mixture: 0.84 (O'Hern et al.); protocols spread it 0.82–0.86.
  assert.ok(s.eta > 0.78 && s.eta < 0.87, `η = ${s.eta}`);
  assert.equal(leading(s.texts.eta), Number(s.eta.toPrecision(5)));
  assert.ok(leading(s.texts.pressure) >= PRESSURE_LIMIT, s.texts.pressure);
  // The thermostat's last step left K/N = kT = 1; the growth's heat went out as negative work.
  assert.ok(Math.abs(s.kineticPerDisk - 1) < 1e-9, `K/N = ${s.kineticPerDisk}`);
  assert.ok(leading(s.texts.work) < 0, s.texts.work);
  // Isostatic: 4 − 4/N' contacts a held disk; a compression this fast may leave a few out.
  assert.ok(s.meanContacts > 3.5 && s.meanContacts <= 4.05, `Z = ${s.meanContacts}`);
  assert.ok(s.rattlers < 30, `${s.rattlers} rattlers`);
  assert.equal(leading(s.texts.contacts), Number(s.meanContacts.toPrecision(4)));
  assert.equal(s.texts.rattlers, `${s.rattlers} of 100`);
  assert.equal(Number(s.texts.pairs), s.pairs);
  assert.ok(s.psi6 < 0.3, `ψ₆ = ${s.psi6}`);
  for (const key of ['collisions', 'time', 'psi6']) assert.ok(leading(s.texts[key]) > 0, key);
  assert.equal(s.audit, '');
  // Jammed, the world stands still.
  await page.waitForTimeout(300);
  assert.equal((await state(page)).time, s.time);
  // New start: a gas again, ready to compress.
  await page.click('#reset');
  const fresh = await state(page);
  assert.equal(fresh.status, 'gas');
  assert.deepEqual(fresh.button, {text: 'Compress', disabled: false});
  assert.ok(Math.abs(fresh.eta - 0.3) < 1e-12, `η = ${fresh.eta}`);
  assert.deepEqual(problems, []);
  await page.close();
});

test('disks of one size compressed alike crystallise', {timeout: JAM_TIMEOUT_MS + 30000},
     async () => {
  const {page, problems} = await openJammed('n=100&mix=mono&rate=0.01&compress=1');
  const s = await state(page);
  await page.screenshot({path: `${OUTPUT}/compress-crystal.png`, fullPage: true});
  assert.equal(s.status, 'jammed');
  assert.ok(s.psi6 > 0.6, `ψ₆ = ${s.psi6}`);
  // Denser than the glass, below the perfect crystal's π/(2√3) = 0.9069.
  assert.ok(s.eta > 0.85 && s.eta < 0.907, `η = ${s.eta}`);
  assert.equal(s.audit, '');
  assert.deepEqual(problems, []);
  await page.close();
});

test('stopping keeps the disks\' size; New start and the cell menu start again',
     {timeout: JAM_TIMEOUT_MS}, async () => {
  const {page, problems} = await openPage(session, 'compress.html?n=100&rate=0.1');
  assert.equal(await readout(page, 'eta'), '0.3');
  assert.equal((await state(page)).status, 'gas');
  await page.click('#compress');
  await page.waitForFunction(() => window.caromCompression.world.packing_fraction() > 0.5, null,
                             {timeout: JAM_TIMEOUT_MS, polling: 50});
  await page.click('#compress');
  assert.equal(await page.textContent('#compress'), 'Compress');
  const stopped = await state(page);
  let later;
  await eventually(async () => (later = await state(page)).time > stopped.time,
                   () => `the gas stands still at t = ${later.time}`);
  assert.equal(later.growth, 0);
  assert.equal(later.eta, stopped.eta);
  assert.ok(later.time > stopped.time, 'the gas runs on');
  assert.equal(later.audit, '');
  await page.click('#reset');
  const fresh = await state(page);
  assert.equal(fresh.eta.toFixed(12), (0.3).toFixed(12));
  assert.ok(fresh.time < later.time);
  await page.selectOption('#boundary', 'box');
  const boxed = await page.evaluate(async () => {
    const {carom} = await import('./js/carom.js');
    return window.caromCompression.world.def().boundary === carom.Boundary.box;
  });
  assert.equal(boxed, true);
  assert.equal((await state(page)).balls, 100);
  assert.deepEqual(problems, []);
  await page.close();
});
