// A static file server for the playground, with nothing but Node's standard library: serves one
// folder on 127.0.0.1 with the MIME types the pages need (application/wasm lets the browser
// compile the module while it downloads). Used by `make playground` and by the tests.
//
//   node web/serve.mjs [FOLDER] [PORT]     (defaults: build/wasm/web/site, 8080; PORT 0 picks one)
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

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const folder = process.argv[2] ?? 'build/wasm/web/site';
  const server = await serve(folder, Number(process.argv[3] ?? 8080));
  console.log(`carom playground: http://127.0.0.1:${server.address().port}/ (serving ${folder}; ` +
              'Ctrl-C stops)');
}
