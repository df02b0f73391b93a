// SPDX-License-Identifier: GPL-3.0-or-later
// The browser build against the native one, on the same inputs, in one run (scripts/bench-web):
//   - the default method's time in WebAssembly (the JavaScript module in Node) over the native
//     command line's, on random tori of 20,000 and 100,000 points (each the median of --runs runs,
//     each run a fresh process; the reconstruction's own clock, reading excluded), and warm;
//   - the first frame from a local server (navigation to the viewer's first frame drawn);
//   - the frames the page draws per second while 20,000 points reconstruct in its worker;
//   - what a first visit downloads, compressed (gzip -9, as static hosts serve it).
// Speed is measured here, never asserted in the tests. Prints a table; --json FILE writes it.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import {
  launchBrowser, nativeSculpt, openViewer, packageDir, requireFile, runScript, serveSite, siteDir,
  statistics,
} from './support.mjs';
import { torus } from './samples.mjs';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const at = args.indexOf(name);
  return at >= 0 ? args[at + 1] : fallback;
};
const runs = Number(option('--runs', 3));
const sizes = option('--points', '20000,100000').split(',').map(Number);
const jsonPath = option('--json', '');
const scratch = mkdtempSync(join(tmpdir(), 'sculpt-bench-web-'));

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

function xyz(points) {
  const lines = [];
  for (let i = 0; i < points.length; i += 3) {
    lines.push(`${points[i].toPrecision(17)} ${points[i + 1].toPrecision(17)} ${points[i + 2].toPrecision(17)}`);
  }
  return lines.join('\n') + '\n';
}

requireFile(nativeSculpt, 'build the desktop program first (scripts/build)');
const { reconstruct } = await import(join(packageDir, 'sculpt.mjs'));
const report = { runs, reconstruction: [], page: {} };

// Reconstruction: the native command line and the module in Node, each run in a fresh process
// (a first reconstruction pays for the memory it touches first, natively and in WebAssembly
// alike), interleaved run by run; and the module warm, run again in one process.
const once = join(scratch, 'reconstruct-once.mjs');
writeFileSync(once, `
import { readPoints, reconstruct } from ${JSON.stringify(join(packageDir, 'sculpt.mjs'))};
import { readFileSync } from 'node:fs';
const file = readPoints(new Uint8Array(readFileSync(process.argv[2])), 'points.xyz');
console.log(reconstruct(file.points).stats.total_seconds);
`);
for (const count of sizes) {
  const points = torus(count);
  const input = join(scratch, `torus-${count}.xyz`);
  writeFileSync(input, xyz(points));
  const native = [], node = [], warm = [];
  for (let run = 0; run < runs; ++run) {
    const stats = join(scratch, 'stats.json');
    const done = spawnSync(nativeSculpt, ['reconstruct', input, '-o', join(scratch, 'out.off'),
                                          '--stats', stats, '--quiet'], { encoding: 'utf8' });
    if (done.status !== 0) throw new Error(done.stderr);
    native.push(JSON.parse(readFileSync(stats, 'utf8')).total_seconds);
    const fresh = spawnSync(process.execPath, [once, input], { encoding: 'utf8' });
    if (fresh.status !== 0) throw new Error(fresh.stderr);
    node.push(Number(fresh.stdout.trim()));
  }
  reconstruct(points);  // the WebAssembly heap grown and the engine's optimiser warmed
  for (let run = 0; run < runs; ++run) warm.push(reconstruct(points).stats.total_seconds);
  report.reconstruction.push({ points: count, native: median(native), node: median(node),
                               node_warm: median(warm), ratio: median(node) / median(native) });
}

// The page: first frame, frames while 20,000 points reconstruct, the worker's time.
const site = await serveSite();
const browser = await launchBrowser();
try {
  const firstFrames = [], firstResults = [];
  for (let run = 0; run < runs; ++run) {
    const viewer = await openViewer(browser, site.url);
    // Seconds since the navigation began: the first frame drawn, then the example reconstructed
    // (in the worker) and drawn.
    firstFrames.push(await viewer.page.evaluate(() =>
      new Promise((done) => requestAnimationFrame(() => done(performance.now() / 1000)))));
    firstResults.push(await viewer.page.evaluate(async () => {
      await window.sculpt.run('wait\nframes 1\n');
      return performance.now() / 1000;
    }));
    await viewer.page.close();
  }
  report.page.first_frame_seconds = median(firstFrames);
  report.page.first_result_seconds = median(firstResults);

  const viewer = await openViewer(browser, site.url);
  await runScript(viewer, 'wait\n');
  const text = xyz(torus(20000));
  const rates = [], workerSeconds = [];
  for (let run = 0; run < runs; ++run) {
    await viewer.page.evaluate((contents) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([contents], 'torus-20000.xyz'));
      document.getElementById('canvas').dispatchEvent(
        new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
    }, text);
    // Frames drawn per second while the job runs (from its first frame busy to its last).
    const rate = await viewer.page.evaluate(() => new Promise((done) => {
      let first = null;
      const sample = () => {
        const frames = Module._sculpt_frames_drawn(), now = performance.now();
        const running = Module._sculpt_job_running();
        if (running && !first) first = { frames, now };
        if (!running && first) {
          done((frames - first.frames) / ((now - first.now) / 1000));
          return;
        }
        setTimeout(sample, 50);
      };
      sample();
    }));
    await runScript(viewer, 'wait\n');
    rates.push(rate);
    workerSeconds.push((await statistics(viewer)).total_seconds);
  }
  report.page.frames_per_second_while_reconstructing_20000 = median(rates);
  report.page.worker_seconds_20000 = median(workerSeconds);
  await viewer.page.close();
} finally {
  await browser.close();
  site.server.close();
}

// What a first visit downloads: the page, its scripts, the viewer and the core (the CGAL meshes
// are fetched only by the figures that read them).
const compressed = (file) => gzipSync(readFileSync(file), { level: 9 }).length;
let firstVisit = 0, meshes = 0;
const walk = (folder) => {
  for (const name of readdirSync(folder)) {
    const path = join(folder, name);
    if (statSync(path).isDirectory()) {
      walk(path);
    } else if (folder.endsWith('meshes')) {
      meshes += compressed(path);
    } else if (!/\.(md|ts|json)$|LICENSE/.test(name)) {
      firstVisit += compressed(path);
    }
  }
};
walk(siteDir);
report.download = { first_visit_mb: firstVisit / 1e6, figure_meshes_mb: meshes / 1e6 };

console.log(`Web against native, the default method on a random torus, median of ${runs} runs`);
console.log('(the reconstruction\'s own clock, reading excluded; each run a fresh process):');
console.log('| points | native | WebAssembly (Node) | web / native | WebAssembly, warm |');
console.log('|---:|---:|---:|---:|---:|');
for (const row of report.reconstruction) {
  console.log(`| ${row.points.toLocaleString('en')} | ${row.native.toFixed(3)} s | ${row.node.toFixed(3)} s | ` +
              `${row.ratio.toFixed(2)} | ${row.node_warm.toFixed(3)} s |`);
}
console.log(`first frame from a local server: ${report.page.first_frame_seconds.toFixed(2)} s` +
            ` (the star reconstructed and drawn: ${report.page.first_result_seconds.toFixed(2)} s)`);
console.log(`frames per second while 20,000 points reconstruct: ${report.page.frames_per_second_while_reconstructing_20000.toFixed(1)}` +
            ` (the worker's reconstruction, every stage kept: ${report.page.worker_seconds_20000.toFixed(2)} s)`);
console.log(`download of a first visit: ${report.download.first_visit_mb.toFixed(2)} MB compressed` +
            ` (+ ${report.download.figure_meshes_mb.toFixed(2)} MB of CGAL meshes for the figures that read them)`);
if (jsonPath) writeFileSync(jsonPath, JSON.stringify(report, null, 2) + '\n');
