// Every page loads, runs its module and draws without a single console error, at a desktop's
// width and at a phone's; a screenshot of each goes to the output folder for a person to look at.
import assert from 'node:assert/strict';
import {after, before, test} from 'node:test';

import {OUTPUT, openBrowser, openPage} from './browser.mjs';

const PAGES = ['index.html', 'two-balls.html', 'walls.html', 'many-balls.html', 'galton.html',
               'pinball.html', 'compress.html', 'pool.html'];
const VIEWPORTS = {
  desktop: {width: 1200, height: 900},
  phone: {width: 390, height: 844},  // a common phone's CSS width
};
const SETTLE_MS = 1500;  // long enough for many frames of Many balls to run and draw

let session;
before(async () => { session = await openBrowser(); });
after(async () => { await session?.close(); });

for (const path of PAGES) {
  for (const [name, viewport] of Object.entries(VIEWPORTS)) {
    test(`${path} at ${name} width: loads with no console errors`, async () => {
      const {page, problems} = await openPage(session, path, viewport);
      await page.waitForTimeout(SETTLE_MS);
      // Readable on a phone: nothing wider than the screen, so no sideways scrolling.
      const overflow = await page.evaluate(
          () => document.documentElement.scrollWidth - document.documentElement.clientWidth);
      await page.screenshot({path: `${OUTPUT}/${path.replace('.html', '')}-${name}.png`,
                             fullPage: true});
      await page.close();
      assert.deepEqual(problems, []);
      assert.ok(overflow <= 0, `the page is ${overflow} px wider than the screen`);
    });
  }
}
