// web/serve.mjs from the command line, as `make playground` runs it: a built folder is served;
// a folder that is not built, a port that is taken and a port that is not a number are each
// refused with one line on stderr (no stack trace) and a non-zero exit status.
import assert from 'node:assert/strict';
import {spawn} from 'node:child_process';
import {mkdtemp, rm, writeFile} from 'node:fs/promises';
import {createServer} from 'node:net';
import {tmpdir} from 'node:os';
import {join, resolve} from 'node:path';
import {after, before, test} from 'node:test';

import {REPO} from './browser.mjs';

const SERVE = resolve(REPO, 'web/serve.mjs');

let built;    // a folder holding what a built site holds (the files' content does not matter)
let unbuilt;  // an empty folder
before(async () => {
  built = await mkdtemp(join(tmpdir(), 'carom-site-'));
  for (const name of ['index.html', 'carom_web.js', 'carom_web.wasm']) {
    await writeFile(join(built, name), name === 'index.html' ? '<!doctype html><p>built' : '');
  }
  unbuilt = await mkdtemp(join(tmpdir(), 'carom-empty-'));
});
after(async () => {
  await rm(built, {recursive: true, force: true});
  await rm(unbuilt, {recursive: true, force: true});
});

// Runs serve.mjs with args until it exits; its status and what it printed.
function runServe(args) {
  return new Promise((done) => {
    const child = spawn(process.execPath, [SERVE, ...args]);
    let out = '';
    let err = '';
    child.stdout.on('data', (d) => { out += d; });
    child.stderr.on('data', (d) => { err += d; });
    child.on('close', (status) => done({status, out, err}));
  });
}

function assertOneLine(err, ...parts) {
  assert.equal(err.split('\n').filter((line) => line !== '').length, 1, err);
  assert.match(err, /^carom playground: /);
  assert.doesNotMatch(err, /^\s+at /m, 'no stack trace');
  for (const part of parts) assert.ok(err.includes(part), `${JSON.stringify(err)} names ${part}`);
}

test('a port that another program holds is refused in one line, exit status 1', async () => {
  const holder = createServer();
  await new Promise((done) => holder.listen(0, '127.0.0.1', done));
  const {port} = holder.address();
  try {
    const {status, out, err} = await runServe([built, String(port)]);
    assert.equal(status, 1);
    assert.equal(out, '');
    assertOneLine(err, `port ${port} is in use`, `PORT=${port + 1}`);
  } finally {
    await new Promise((done) => holder.close(done));
  }
});

test('a folder that is not a built site is refused, naming what is missing', async () => {
  for (const folder of [unbuilt, join(unbuilt, 'no-such-folder')]) {
    const {status, out, err} = await runServe([folder, '0']);
    assert.equal(status, 1);
    assert.equal(out, '');
    assertOneLine(err, folder, 'index.html is missing', 'make wasm');
  }
});

test('a port that is not a number is refused', async () => {
  for (const port of ['eighty', '-1', '70000', '']) {
    const {status, err} = await runServe([built, port]);
    assert.equal(status, 2, port);
    assertOneLine(err, `PORT "${port}"`, '0 to 65535');
  }
});

test('a built folder is served on the port given', async () => {
  const child = spawn(process.execPath, [SERVE, built, '0']);
  try {
    const line = await new Promise((done, fail) => {
      child.stdout.once('data', (d) => done(String(d)));
      child.once('close', (status) => fail(new Error(`exited with ${status}`)));
    });
    const url = line.match(/http:\/\/127\.0\.0\.1:\d+\//)?.[0];
    assert.ok(url, line);
    const response = await fetch(url);
    assert.equal(response.status, 200);
    assert.equal(response.headers.get('content-type'), 'text/html; charset=utf-8');
    assert.equal(await response.text(), '<!doctype html><p>built');
  } finally {
    child.kill();
  }
});
