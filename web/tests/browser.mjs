// What every playground test and the benchmark share: the site served on a free port, and
// Debian's chromium driven by playwright-core, with every console error and page error recorded.
import {mkdir} from 'node:fs/promises';
import {dirname, resolve} from 'node:path';
import {fileURLToPath} from 'node:url';

import {chromium} from 'playwright-core';

import {serve, siteProblem} from '../serve.mjs';

const here = dirname(fileURLToPath(import.meta.url));
export const REPO = resolve(here, '..', '..');
export const SITE = process.env.CAROM_WEB_SITE ?? resolve(REPO, 'build/wasm/web/site');
export const OUTPUT = process.env.CAROM_WEB_OUTPUT ?? resolve(REPO, 'build/web-test-output');
export const CAROM_CLI = process.env.CAROM_CLI ?? resolve(REPO, 'build/release/apps/carom/carom');

const CHROMIUM = process.env.CAROM_CHROMIUM ?? '/usr/bin/chromium';
const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
                       '--disable-background-networking', '--disable-component-update',
                       '--disable-sync'];

// Starts the server and the browser; close() stops both.
export async function openBrowser() {
  await mkdir(OUTPUT, {recursive: true});
  const problem = await siteProblem(SITE);
  if (problem) throw new Error(`${problem}; or set CAROM_WEB_SITE to a built site`);
  const server = await serve(SITE, 0);
  const browser = await chromium.launch({executablePath: CHROMIUM, headless: true,
                                         args: CHROMIUM_ARGS});
  const base = `http://127.0.0.1:${server.address().port}/`;
  return {
    browser,
    base,
    async close() {
      await browser.close();
      await new Promise((done) => server.close(done));
    },
  };
}

// Opens path in a new page of the given size and waits until its script has run
// (body[data-ready]). problems lists every console error and uncaught exception, as text.
export async function openPage(session, path, viewport = {width: 1200, height: 900}) {
  const page = await session.browser.newPage({viewport});
  return {page, problems: await loadRecordingProblems(session, page, path)};
}

// The same on a phone-sized screen that takes touches, in a browser context of its own: close
// the context (which closes the page) when done.
export async function openTouchPage(session, path) {
  const context = await session.browser.newContext({hasTouch: true,
                                                    viewport: {width: 390, height: 844}});
  const page = await context.newPage();
  return {context, page, problems: await loadRecordingProblems(session, page, path)};
}

async function loadRecordingProblems(session, page, path) {
  const problems = [];
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()}`));
  await page.goto(session.base + path);
  await page.waitForSelector('body[data-ready="true"]', {timeout: 20000});
  return problems;
}

// The text of the element marked data-readout="key".
export async function readout(page, key) {
  return (await page.textContent(`[data-readout="${key}"]`)).trim();
}

// Waits until check() (async, run here) returns true: a page changes what it shows on its next
// frame or report, and a loaded machine gives fewer frames a second, so a test waits for the
// change itself, never for a fixed time. Fails with describe()'s text (the last state seen).
export async function eventually(check, describe, timeout = 20000) {
  const deadline = Date.now() + timeout;
  while (!(await check())) {
    if (Date.now() > deadline) throw new Error(`not within ${timeout} ms: ${await describe()}`);
    await new Promise((done) => setTimeout(done, 20));
  }
}

// Waits until the readout `key` shows `expected` (a string, or a RegExp it must match) and
// returns its text.
export async function expectReadout(page, key, expected, timeout = 20000) {
  const shows = (text) => (expected instanceof RegExp ? expected.test(text) : text === expected);
  let text = await readout(page, key);
  await eventually(async () => shows(text = await readout(page, key)),
                   () => `the readout ${key} shows '${text}', not ${expected}`, timeout);
  return text;
}
