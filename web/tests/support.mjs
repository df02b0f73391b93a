// SPDX-License-Identifier: GPL-3.0-or-later
// What the browser tests share: the site served on a loopback port, Debian's chromium headless
// (SwiftShader's WebGL 2), a page of the viewer whose console is watched, viewer scripts run in
// it with their output, downloads caught, and pictures read as pixels.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, existsSync, readdirSync, statSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';
import { PNG } from 'pngjs';

const here = fileURLToPath(new URL('.', import.meta.url));
export const projectRoot = resolve(here, '../..');
export const siteDir = process.env.SCULPT_SITE ?? join(projectRoot, 'build-web/site');
export const packageDir = process.env.SCULPT_PACKAGE ?? join(projectRoot, 'build-web/package');
export const nativeSculpt = process.env.SCULPT_EXECUTABLE ?? join(projectRoot, 'build/sculpt');

// No silent skips: a test that lacks what it reads fails and says what is missing.
export function requireFile(path, how) {
  if (!existsSync(path)) throw new Error(`${path} is missing: ${how}`);
  return path;
}

const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.svg': 'image/svg+xml', '.json': 'application/json',
  '.off': 'text/plain', '.ts': 'text/plain', '.md': 'text/plain',
};

// The site as a static host serves it: files only, no special headers.
export async function serveSite() {
  requireFile(join(siteDir, 'index.html'), 'build the site first (scripts/web)');
  const server = createServer((request, response) => {
    const path = normalize(decodeURIComponent(new URL(request.url, 'http://x').pathname));
    let file = join(siteDir, path);
    if (!file.startsWith(siteDir)) {
      response.writeHead(403).end();
      return;
    }
    if (existsSync(file) && statSync(file).isDirectory()) file = join(file, 'index.html');
    if (!existsSync(file)) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { 'Content-Type': types[extname(file)] ?? 'application/octet-stream' });
    response.end(readFileSync(file));
  });
  await new Promise((done) => server.listen(0, '127.0.0.1', done));
  return { server, url: `http://127.0.0.1:${server.address().port}/` };
}

export async function launchBrowser() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-gl=swiftshader', '--enable-unsafe-swiftshader',
           '--ignore-gpu-blocklist', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
           '--disable-features=Translate,MediaRouter'],
  });
}

// SwiftShader reports its own slow paths as console warnings; they are the machine's, not ours.
const machineMessages = [/GL Driver Message/, /GPU stall due to ReadPixels/, /Automatic fallback to software WebGL/];

// A page of the viewer at `query` ("?example=torus"), started: its console errors, every line it
// printed, and its downloads (caught into a folder of their own).
export async function openViewer(browser, siteUrl, query = '', { width = 1280, height = 720, hasTouch = false } = {}) {
  const page = await browser.newPage();
  await page.setViewport({ width, height, hasTouch });
  const viewer = { page, errors: [], lines: [], downloads: mkdtempSync(join(tmpdir(), 'sculpt-downloads-')) };
  page.on('console', (message) => {
    const text = message.text();
    if (machineMessages.some((pattern) => pattern.test(text))) return;
    viewer.lines.push(text);
    if (message.type() === 'error') viewer.errors.push(text);
  });
  page.on('pageerror', (error) => viewer.errors.push(`page error: ${error.message}`));
  page.on('requestfailed', (request) =>
    viewer.errors.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  const session = await page.createCDPSession();
  await session.send('Browser.setDownloadBehavior',
                     { behavior: 'allow', downloadPath: viewer.downloads, eventsEnabled: true });
  await page.bringToFront();
  const started = Date.now();
  await page.goto(siteUrl + query, { waitUntil: 'load' });
  await page.waitForFunction(() => window.sculpt?.started || window.sculpt?.errors.length > 0,
                             { timeout: 60000 });
  viewer.startSeconds = (Date.now() - started) / 1000;
  return viewer;
}

// Runs viewer script commands (src/viewer/script.hpp) in the page; their output lines.
export async function runScript(viewer, script, { expectSuccess = true } = {}) {
  const before = viewer.lines.length;
  const succeeded = await viewer.page.evaluate((text) => window.sculpt.run(text), script);
  if (expectSuccess && !succeeded) {
    throw new Error(`the script failed:\n${script}\n${viewer.lines.slice(before).join('\n')}`);
  }
  // Console messages arrive asynchronously: let those the script printed come in.
  await new Promise((done) => setTimeout(done, 100));
  return { succeeded, lines: viewer.lines.slice(before) };
}

// The JSON of a "stats: {...}" line the script printed.
export async function statistics(viewer) {
  const { lines } = await runScript(viewer, 'stats\n');
  const line = lines.find((text) => text.startsWith('stats: '));
  if (!line) throw new Error(`no statistics printed: ${lines.join('\n')}`);
  return JSON.parse(line.slice(7));
}

export async function message(viewer) {
  const { lines } = await runScript(viewer, 'message\n');
  return lines.find((text) => text.startsWith('message: '))?.slice(9) ?? '';
}

// A download that has arrived whole: its bytes.
export async function download(viewer, name, timeoutMs = 30000) {
  const path = join(viewer.downloads, name);
  const start = Date.now();
  for (;;) {
    const files = readdirSync(viewer.downloads);
    if (files.includes(name) && !files.some((file) => file.endsWith('.crdownload'))) {
      return readFileSync(path);
    }
    if (Date.now() - start > timeoutMs) {
      throw new Error(`no download ${name} in ${viewer.downloads} (${files.join(', ')})`);
    }
    await new Promise((done) => setTimeout(done, 100));
  }
}

// The page as pixels: {width, height, data (RGBA)}.
export async function screenshot(viewer, clip) {
  return PNG.sync.read(Buffer.from(await viewer.page.screenshot({ type: 'png', clip })));
}

export function readPng(bytes) {
  return PNG.sync.read(bytes);
}

// The share of pixels in a region that differ from the background (white) by more than a little.
export function drawnShare(image, x0 = 0, y0 = 0, x1 = image.width, y1 = image.height) {
  let drawn = 0;
  for (let y = y0; y < y1; ++y) {
    for (let x = x0; x < x1; ++x) {
      const i = 4 * (y * image.width + x);
      if (image.data[i] < 235 || image.data[i + 1] < 235 || image.data[i + 2] < 235) ++drawn;
    }
  }
  return drawn / ((x1 - x0) * (y1 - y0));
}

// The share of pixels whose channels differ by more than `tolerance` (the golden images' rule),
// over two pictures of one size.
export function mismatchShare(a, b, tolerance) {
  if (a.width !== b.width || a.height !== b.height) return 1;
  let differ = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (Math.abs(a.data[i] - b.data[i]) > tolerance || Math.abs(a.data[i + 1] - b.data[i + 1]) > tolerance ||
        Math.abs(a.data[i + 2] - b.data[i + 2]) > tolerance) ++differ;
  }
  return differ / (a.width * a.height);
}

// The share of pixels that changed between two pictures of one size.
export function changedShare(a, b) {
  return mismatchShare(a, b, 8);
}

// Runs the native command line (the desktop build) and returns what it printed.
export function runNative(args, cwd = undefined) {
  requireFile(nativeSculpt, 'build the desktop program first (scripts/build)');
  const run = spawnSync(resolve(nativeSculpt), args,
                        { cwd, encoding: 'utf8', env: { ...process.env, GALLIUM_DRIVER: 'llvmpipe' } });
  return { status: run.status, stdout: run.stdout, stderr: run.stderr };
}

// Pixels as an image the tests write beside a failure (actual, expected, difference).
export function writePng(path, image) {
  const png = new PNG({ width: image.width, height: image.height });
  image.data.copy ? image.data.copy(png.data) : png.data.set(image.data);
  return import('node:fs').then((fs) => fs.writeFileSync(path, PNG.sync.write(png)));
}
