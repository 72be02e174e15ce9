// A static file server for the playground, with nothing but Node's standard library: serves one
// folder on 127.0.0.1 with the MIME types the pages need (application/wasm lets the browser
// compile the module while it downloads). Used by `make playground` and by the tests.
//
//   node web/serve.mjs [FOLDER] [PORT]     (defaults: build/wasm/web/site, 8080; PORT 0 picks one)
//
// It refuses a folder that is not a built site, and a port that is taken, with one line saying
// what to do, and a non-zero exit status.
import {createReadStream} from 'node:fs';
import {stat} from 'node:fs/promises';
import {createServer} from 'node:http';
import {extname, join, normalize, resolve, sep} from 'node:path';
import {fileURLToPath} from 'node:url';

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
};

// What the wasm build puts in the site folder (web/CMakeLists.txt): without these the pages
// cannot run.
const BUILT_FILES = ['index.html', 'carom_web.js', 'carom_web.wasm'];

// Why folder is not a built playground site, or null when it is.
export async function siteProblem(folder) {
  for (const name of BUILT_FILES) {
    const file = join(folder, name);
    const found = await stat(file).then((s) => s.isFile(), () => false);
    if (!found) {
      return `${folder} is not a built playground: ${name} is missing (build it with: make wasm)`;
    }
  }
  return null;
}

// Resolves to the listening server; its address().port is the port in use.
export function serve(folder, port = 8080, host = '127.0.0.1') {
  const root = resolve(folder);
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url, 'http://x').pathname);
    let file = normalize(join(root, path));
    if (file !== root && !file.startsWith(root + sep)) {
      response.writeHead(403).end('outside the site');
      return;
    }
    try {
      if ((await stat(file)).isDirectory()) file = join(file, 'index.html');
      await stat(file);
    } catch {
      response.writeHead(404, {'Content-Type': 'text/plain'}).end(`not found: ${path}`);
      return;
    }
    response.writeHead(200, {'Content-Type': TYPES[extname(file)] ?? 'application/octet-stream',
                             'Cache-Control': 'no-store'});
    createReadStream(file).pipe(response);
  });
  return new Promise((done, fail) => {
    server.once('error', fail);
    server.listen(port, host, () => done(server));
  });
}

// Why listening on port failed, in words, with what to do about it.
function listenProblem(error, port) {
  const another = port < 65535 ? port + 1 : 8080;
  if (error.code === 'EADDRINUSE') {
    return `port ${port} is in use by another program; choose another port, e.g. ` +
           `make playground PORT=${another}`;
  }
  if (error.code === 'EACCES') {
    return `port ${port} needs more rights than this user has; choose a port from 1024 up, e.g. ` +
           `make playground PORT=8080`;
  }
  return `cannot listen on 127.0.0.1:${port}: ${error.message}`;
}

function stop(status, message) {
  console.error(`carom playground: ${message}`);
  process.exit(status);
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const folder = process.argv[2] ?? 'build/wasm/web/site';
  const portText = process.argv[3] ?? '8080';
  const port = Number(portText);
  if (!/^\d+$/.test(portText) || port > 65535) {
    stop(2, `PORT "${portText}" is not a port number (0 to 65535; 0 picks a free one)`);
  }
  const problem = await siteProblem(folder);
  if (problem) stop(1, problem);
  const server = await serve(folder, port).catch((error) => stop(1, listenProblem(error, port)));
  console.log(`carom playground: http://127.0.0.1:${server.address().port}/ (serving ${folder}; ` +
              'Ctrl-C stops)');
}
