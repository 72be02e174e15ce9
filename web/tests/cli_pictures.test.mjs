// The SVG pictures of the native `carom` tool, measured in the browser with the fonts it really
// has: every line of text ends inside the picture (a plot's long subtitle wraps rather than run
// past the right edge).
import assert from 'node:assert/strict';
import {execFileSync} from 'node:child_process';
import {mkdtemp, readFile, rm} from 'node:fs/promises';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {after, before, test} from 'node:test';

import {CAROM_CLI, REPO, openBrowser} from './browser.mjs';

let session;
let dir;
before(async () => {
  session = await openBrowser();
  dir = await mkdtemp(join(tmpdir(), 'carom-pictures-'));
});
after(async () => {
  await session?.close();
  if (dir) await rm(dir, {recursive: true, force: true});
});

const example = (name) => resolve(REPO, 'examples', name);

const PICTURES = {
  'momentum plot': ['render', example('billiards-frictionless.json'), '--plot', 'momentum', '--until', '2'],
  'energy plot': ['render', example('pinball.json'), '--plot', 'energy', '--until', '1'],
  'rate plot': ['render', example('box-of-1000.json'), '--plot', 'rate', '--until', '1'],
  'scene picture': ['render', example('pinball.json'), '--at', '1', '--arrows', '--color', 'speed'],
  'sweep figure': ['sweep', '--a', '0,0,1', '--va', '6,2', '--b', '8,3,1.5', '--vb', '-4,-1'],
};

for (const [name, args] of Object.entries(PICTURES)) {
  test(`${name}: every line of text ends inside the picture`, async () => {
    const file = join(dir, `${name.replace(/ /g, '-')}.svg`);
    execFileSync(CAROM_CLI, [...args, args[0] === 'sweep' ? '--svg' : '--out', file]);
    const svg = (await readFile(file, 'utf8')).replace(/^<\?xml[^>]*>\s*/, '');
    const page = await session.browser.newPage();
    await page.setContent(`<!doctype html><body style="margin:0">${svg}</body>`);
    const {width, outside, lines} = await page.evaluate(() => {
      const picture = document.querySelector('svg');
      const pictureWidth = Number(picture.getAttribute('width'));
      const texts = [...picture.querySelectorAll('text')];
      const out = [];
      for (const text of texts) {
        // In the picture's own units: its viewBox is its size.
        const box = text.getBBox();
        const matrix = text.getCTM();
        const left = matrix.a * box.x + matrix.c * box.y + matrix.e;
        const right = matrix.a * (box.x + box.width) + matrix.c * box.y + matrix.e;
        if (Math.min(left, right) < 0 || Math.max(left, right) > pictureWidth) {
          out.push(`${text.textContent} (${left.toFixed(1)} to ${right.toFixed(1)})`);
        }
      }
      return {width: pictureWidth, outside: out, lines: texts.length};
    });
    assert.ok(lines > 3, `${lines} texts`);
    assert.deepEqual(outside, [], `in a picture ${width} wide`);
    await page.close();
  });
}
