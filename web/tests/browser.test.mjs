// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer in a real browser (Debian's chromium, headless, WebGL 2 on SwiftShader), from the
// site as a static host serves it: it loads without a console error; every built-in example
// draws and its stages differ; a click and a tap add samples and the verdict follows; every
// figure's panels are reached from its link; a dropped file reconstructs and a bad one is refused
// in the command line's words; pictures match the native renderer's; it keeps drawing while a
// reconstruction runs in its worker and cancels at once; downloads arrive whole; a link opens
// the view it was copied from; side by side runs its methods in workers of their own; the
// shipped lessons run to their end from Page Down alone.
import assert from 'node:assert/strict';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, describe, test } from 'node:test';
import {
  changedShare, download, drawnShare, launchBrowser, message, mismatchShare, openViewer, readPng,
  runNative, runScript, screenshot, serveSite, statistics, writePng,
} from './support.mjs';

const scratch = mkdtempSync(join(tmpdir(), 'sculpt-browser-'));
const panelWidth = 360;  // the viewer's panel at text scale 1 (src/viewer/viewer.cpp)
let site, browser;

before(async () => {
  site = await serveSite();
  browser = await launchBrowser();
});

after(async () => {
  await browser?.close();
  site?.server.close();
});

// The picture right of the panel, below the menu bar.
function picture(viewer) {
  const { width, height } = viewer.page.viewport();
  return screenshot(viewer, { x: panelWidth, y: 24, width: width - panelWidth, height: height - 24 });
}

// A key held as a hand holds it, over a few frames: Dear ImGui 1.86 reads the keys' state once
// a frame, and a press and release between two frames would go unseen.
// A bare tap, its press and release in the same moment, as a presentation remote sends it: the
// viewer acts on it even when no frame falls between the two.
async function press(viewer, key) {
  await viewer.page.focus('#canvas');
  await viewer.page.keyboard.press(key);
}

async function close(viewer) {
  assert.deepEqual(viewer.errors, [], 'console errors');
  await viewer.page.close();
}

function torusText(count, seed = 5) {
  let state = seed;
  const random = () => (state = (state * 48271) % 2147483647) / 2147483647;
  let text = '';
  for (let i = 0; i < count; ++i) {
    const u = 2 * Math.PI * random(), v = 2 * Math.PI * random();
    text += `${(1 + 0.4 * Math.cos(v)) * Math.cos(u)} ${(1 + 0.4 * Math.cos(v)) * Math.sin(u)} ${0.4 * Math.sin(v)}\n`;
  }
  return text;
}

// Drops a file on the canvas as a user's drag and drop does, and waits until the viewer has
// asked for its reconstruction (the browser reads a dropped file before handing it over).
async function drop(viewer, name, text) {
  const before = await viewer.page.evaluate(() => Module.sculptJobs.started);
  await viewer.page.evaluate((fileName, contents) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([contents], fileName));
    const canvas = document.getElementById('canvas');
    canvas.dispatchEvent(new DragEvent('dragover', { dataTransfer: transfer, bubbles: true, cancelable: true }));
    canvas.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
  }, name, text);
  await viewer.page.waitForFunction((count) => Module.sculptJobs.started > count, { timeout: 30000 }, before);
}

test('the page loads with no console error and shows the default example', async () => {
  const viewer = await openViewer(browser, site.url);
  await runScript(viewer, 'wait\nframes 3\n');
  const stats = await statistics(viewer);
  assert.equal(stats.samples, 200);  // the star
  assert.match(stats.verdict, /closed curve/);
  assert.ok(drawnShare(await picture(viewer)) > 0.01, 'the picture is blank');
  console.log(`first frame after ${viewer.startSeconds.toFixed(2)} s from the navigation`);
  await close(viewer);
});

test('every built-in example draws, and its stages differ', async () => {
  const examples = runNative(['examples']).stdout.trim().split('\n').map((line) => line.trim().split(/\s+/)[0]);
  assert.ok(examples.length >= 20, `examples: ${examples}`);
  const viewer = await openViewer(browser, site.url);
  for (const example of examples) {
    await runScript(viewer, `example ${example}\nwait\nframes 2\n`);
    const stats = await statistics(viewer);
    assert.ok(stats.samples > 0, example);
    const share = drawnShare(await picture(viewer));
    assert.ok(share > 0.003, `${example}: the picture is blank (${share})`);
  }
  for (const example of ['star', 'bumpy']) {
    await runScript(viewer, `example ${example}\nwait\nstage delaunay\nframes 2\n`);
    const delaunay = await picture(viewer);
    await runScript(viewer, 'stage poles\nframes 2\n');
    const poles = await picture(viewer);
    await runScript(viewer, 'stage surface\nframes 2\n');
    const surface = await picture(viewer);
    assert.ok(changedShare(delaunay, poles) > 0.01, `${example}: delaunay and poles look alike`);
    assert.ok(changedShare(poles, surface) > 0.01, `${example}: poles and surface look alike`);
  }
  await close(viewer);
});

test('a click adds a sample, a tap another, and the verdict follows', async () => {
  const viewer = await openViewer(browser, site.url, '?example=star', { width: 1280, height: 720, hasTouch: true });
  await runScript(viewer, 'wait\nframes 2\n');
  const before = await statistics(viewer);
  await press(viewer, 'e');  // edit with the mouse
  await runScript(viewer, 'frames 2\n');
  // The star's centre, middle of the picture: inside the curve, far from every sample.
  const { width, height } = viewer.page.viewport();
  const centre = { x: panelWidth + (width - panelWidth) / 2, y: 24 + (height - 24) / 2 };
  await viewer.page.mouse.click(centre.x, centre.y);
  await runScript(viewer, 'frames 2\nwait\n');
  const clicked = await statistics(viewer);
  assert.equal(clicked.samples, before.samples + 1);
  assert.notEqual(clicked.verdict, before.verdict);
  await viewer.page.touchscreen.tap(centre.x + 40, centre.y + 30);
  await runScript(viewer, 'frames 2\nwait\n');
  const tapped = await statistics(viewer);
  assert.equal(tapped.samples, before.samples + 2);
  await close(viewer);
});

test('every figure of the paper opens from its link and reaches each of its panels', async () => {
  const first = await openViewer(browser, site.url);
  const { lines } = await runScript(first, 'figures\n');
  const figures = JSON.parse(lines.find((line) => line.startsWith('figures: ')).slice(9));
  await close(first);
  assert.ok(figures.length >= 15);
  for (const figure of figures) {
    const viewer = await openViewer(browser, site.url, `?figure=${figure.id}`);
    for (const [index, panel] of figure.panels.entries()) {
      const step = index === 0 ? '' : 'panel next\n';
      await runScript(viewer, `${step}wait\nexpect-panel ${panel}\nframes 2\n`);
      const share = drawnShare(await picture(viewer));
      assert.ok(share > 0.002, `${panel}: the picture is blank (${share})`);
    }
    await close(viewer);
  }
  // A panel of its own: ?figure=fig06&panel=c.
  const viewer = await openViewer(browser, site.url, '?figure=fig06&panel=c');
  await runScript(viewer, 'wait\nexpect-panel fig06c\n');
  // Once loaded, the page needs no network: the figures' meshes came while it was idle.
  await viewer.page.waitForFunction(() => window.sculpt.meshesLoaded, { timeout: 30000 });
  await viewer.page.setOfflineMode(true);
  await runScript(viewer, 'figure fig11\nwait\nexpect-panel fig11\nfigure fig15\nwait\n');
  await viewer.page.setOfflineMode(false);
  await close(viewer);
});

test('a dropped file reconstructs; a bad one is refused on screen in the command line\'s words', async () => {
  const viewer = await openViewer(browser, site.url);
  await runScript(viewer, 'wait\n');
  await drop(viewer, 'ring.xyz', torusText(2500));
  await runScript(viewer, 'wait\nframes 2\n');
  const stats = await statistics(viewer);
  assert.equal(stats.samples, 2500);
  assert.match(stats.verdict, /genus 1/);
  assert.match(await message(viewer), /ring\.xyz/);

  const bad = 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n1\n2\n';
  writeFileSync(join(scratch, 'bad.ply'), bad);
  const native = runNative(['reconstruct', 'bad.ply', '-o', 'x.stl'], scratch);
  const refusal = native.stderr.trim().split('\n').pop().replace(/^sculpt: /, '');
  await drop(viewer, 'bad.ply', bad);
  await runScript(viewer, 'wait-idle\nframes 2\n');
  assert.equal(await message(viewer), refusal);
  await close(viewer);
});

test('a 2D and a 3D stage match the native renderer\'s pictures of them', async () => {
  for (const [example, stage] of [['star', 'poles'], ['bumpy', 'surface']]) {
    const viewer = await openViewer(browser, site.url, `?example=${example}&stage=${stage}`);
    await runScript(viewer, `wait\nstage ${stage}\ncamera orbit 20 10\ncamera save /view.json\n` +
                            'export /web.png 640x480\n');
    writeFileSync(join(scratch, 'view.json'), await download(viewer, 'view.json'));
    const web = readPng(await download(viewer, 'web.png'));
    const nativePath = join(scratch, `${example}-native.png`);
    const run = runNative(['render', '--example', example, '--stage', stage, '--camera',
                           join(scratch, 'view.json'), '--size', '640x480', '-o', nativePath]);
    assert.equal(run.status, 0, run.stderr);
    const native = readPng((await import('node:fs')).readFileSync(nativePath));
    // SwiftShader and llvmpipe rasterise the same triangles; they differ at antialiased edges.
    const share = mismatchShare(web, native, 48);
    console.log(`${example} ${stage}: ${(100 * share).toFixed(2)}% of pixels differ beyond 48/255`);
    if (share > 0.03) await writePng(join(scratch, `${example}-web.png`), web);
    assert.ok(share <= 0.03, `${example} ${stage}: ${(100 * share).toFixed(2)}% differ; see ${scratch}`);
    await close(viewer);
  }
});

test('the page keeps drawing while 20,000 points reconstruct in the worker, and cancels at once', async () => {
  const viewer = await openViewer(browser, site.url);
  await runScript(viewer, 'wait\n');
  await drop(viewer, 'torus-20k.xyz', torusText(20000));
  // The frames drawn while it runs. Not a speed (scripts/bench-web measures that): that the page
  // is not blocked.
  const framesWhileRunning = await viewer.page.evaluate(() => new Promise((done) => {
    let frames = 0, last = Module._sculpt_frames_drawn();
    const watch = () => {
      const now = Module._sculpt_frames_drawn();
      if (Module._sculpt_job_running() !== 1) return done(frames);
      frames += now - last;
      last = now;
      setTimeout(watch, 10);
    };
    watch();
  }));
  assert.ok(framesWhileRunning >= 3, `${framesWhileRunning} frames drawn while the worker ran`);
  await runScript(viewer, 'wait\n');
  assert.equal((await statistics(viewer)).samples, 20000);
  // A larger one, cancelled: no reconstruction runs any more from the cancel's own frame.
  await drop(viewer, 'torus-100k.xyz', torusText(100000));
  await runScript(viewer, 'frames 2\nexpect-busy\ncancel\nexpect-idle\nwait-idle\n');
  assert.equal(await message(viewer), 'cancelled');
  await close(viewer);
});

test('pictures, animations, results and samples arrive as downloads', async () => {
  const viewer = await openViewer(browser, site.url, '?example=star&stage=propagation');
  await runScript(viewer, 'wait\nexport /star.png 320x240\nexport-animation /replay.webp 160x120 4\n' +
                          'save-result /star.svg\nsave-points /star.xy\n');
  assert.equal(readPng(await download(viewer, 'star.png')).width, 320);
  const webp = await download(viewer, 'replay.webp');
  assert.equal(webp.subarray(0, 4).toString(), 'RIFF');
  assert.equal(webp.subarray(8, 12).toString(), 'WEBP');
  assert.ok(webp.includes(Buffer.from('ANMF')), 'not an animation');
  assert.match((await download(viewer, 'star.svg')).toString(), /<svg/);
  assert.equal((await download(viewer, 'star.xy')).toString().trim().split('\n').length, 200);
  await runScript(viewer, 'example torus\nwait\nsave-result /torus.ply\n');
  assert.match((await download(viewer, 'torus.ply')).subarray(0, 40).toString(), /^ply/);
  await close(viewer);
});

test('a link copied from a view opens that view', async () => {
  const viewer = await openViewer(browser, site.url, '?example=torus&method=paper');
  const { lines } = await runScript(viewer, 'wait\nstage poles\npick-sample 7\nlink\n');
  const link = lines.find((line) => line.startsWith('link: ')).slice(6);
  assert.equal(new URL(link).search, '?example=torus&method=paper&stage=poles&sample=7');
  await close(viewer);
  const opened = await openViewer(browser, link.replace(/\?.*/, ''), new URL(link).search);
  await runScript(opened, 'wait\nframes 2\n');
  const again = await runScript(opened, 'link\n');
  assert.ok(again.lines.includes(`link: ${link.replace(/^http:\/\/[^/]+\//, site.url)}`), again.lines.join('\n'));
  assert.equal((await statistics(opened)).method, 'paper');
  await close(opened);
});

test('a class opens a presentation from a link: no panel, the picture the whole width', async () => {
  const address = '?example=star&present=on&palette=colour-blind&scale=2';
  const viewer = await openViewer(browser, site.url, address, { width: 1024, height: 768 });
  const { lines } = await runScript(viewer, 'wait\nframes 2\nlink\n');
  const link = lines.find((line) => line.startsWith('link: ')).slice(6);
  assert.equal(new URL(link).search, address);
  // Where the panel would be (its left 360 pixels, below the menu bar), the picture: mostly
  // white, nothing of the panel's dark grey (src/viewer/panel_colours.hpp: 0.06, 0.06, 0.07).
  const left = await screenshot(viewer, { x: 0, y: 30, width: 360, height: 700 });
  let grey = 0;
  for (let i = 0; i < left.data.length; i += 4) {
    if (Math.abs(left.data[i] - 15) < 6 && Math.abs(left.data[i + 1] - 15) < 6 && Math.abs(left.data[i + 2] - 18) < 6) ++grey;
  }
  assert.ok(grey / (left.width * left.height) < 0.02, `panel grey ${grey}`);
  await close(viewer);
});

test('side by side runs each method in a worker of its own, beside the main one', async () => {
  const viewer = await openViewer(browser, site.url, '?example=star&method=paper');
  await runScript(viewer, 'wait\nframes 2\n');
  const one = await picture(viewer);
  await runScript(viewer, 'compare paper,robust\nwait\nframes 3\n');
  assert.match(await message(viewer), /comparing 2 methods/);
  const two = await picture(viewer);
  await writePng(join(scratch, 'side-by-side.png'), two);
  assert.ok(changedShare(one, two) > 0.01, 'the picture did not change');
  // A star in each half, each drawn (the verdicts above them are text, the rest white).
  const half = Math.floor(two.width / 2);
  const top = Math.floor(two.height * 0.2);
  assert.ok(drawnShare(two, 0, top, half, two.height) > 0.01, 'the left view is empty');
  assert.ok(drawnShare(two, half, top, two.width, two.height) > 0.01, 'the right view is empty');
  // Editing the points ends the comparison, and the main job still answers.
  await runScript(viewer, 'compare off\nmethod robust\nwait\nframes 2\n');
  assert.equal((await statistics(viewer)).method, 'robust');
  await close(viewer);
});

test('the JavaScript module works in the page too', async () => {
  const viewer = await openViewer(browser, site.url);
  const verdict = await viewer.page.evaluate(async () => {
    const { reconstruct } = await import('./sculpt/sculpt.mjs');
    const points = [];
    for (let i = 0; i < 30; ++i) points.push(Math.cos(i * Math.PI / 15), Math.sin(i * Math.PI / 15));
    return reconstruct(points, { dimension: 2 }).verdict.line;
  });
  assert.equal(verdict, 'closed curve: 1 component, all 30 samples on it');
  await close(viewer);
});

test('an unknown option in the address is refused in one line, on the page', async () => {
  const viewer = await openViewer(browser, site.url, '?colour=red');
  assert.ok(viewer.errors.length === 0);
  const shown = await viewer.page.$eval('#status', (status) => (status.hidden ? '' : status.textContent));
  assert.match(shown, /colour/);
  await viewer.page.close();
  // A known option with a wrong value: named as in the address, with the values it takes.
  const stage = await openViewer(browser, site.url, '?example=star&stage=banana');
  const refusal = await stage.page.$eval('#status', (status) => (status.hidden ? '' : status.textContent));
  assert.match(refusal, /stage: no stage 'banana' \(stages: samples, delaunay, /);
  assert.doesNotMatch(refusal, /--help/);
  await stage.page.close();
});

describe('the shipped lessons', () => {
  for (const lesson of ['undersampling', 'comparing']) {
  test(`${lesson} runs to its end from Page Down alone, each step another picture`, async () => {
    // A pause at each picture the lesson takes as a script.
    const script = readFileSync(new URL(`../../examples/lessons/${lesson}.script`, import.meta.url), 'utf8');
    const steps = script.split('\n').filter((line) => line.startsWith('screenshot ')).length;
    assert.ok(steps >= 5, `${lesson}: ${steps} pictures`);
    const viewer = await openViewer(browser, site.url, `?lesson=${lesson}`);
    let previous = null;
    for (let step = 1; step <= steps; ++step) {
      // Paused at the step's picture.
      await viewer.page.waitForFunction(() => Module._sculpt_script_state() === 4, { timeout: 60000 });
      const shot = await picture(viewer);
      await writePng(join(scratch, `${lesson}-step-${step}.png`), shot);
      if (previous) assert.ok(changedShare(previous, shot) > 0.005, `step ${step} looks like the one before`);
      previous = shot;
      await press(viewer, 'PageDown');
      // The key is taken at the next frame: the lesson leaves its pause.
      await viewer.page.waitForFunction(() => Module._sculpt_script_state() !== 4, { timeout: 10000 })
        .catch(() => assert.fail(`Page Down at step ${step} did not go on`));
    }
    await viewer.page.waitForFunction(() => Module._sculpt_script_state() === 2, { timeout: 60000 });
    await close(viewer);
  });
  }
});
