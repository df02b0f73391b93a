// SPDX-License-Identifier: GPL-3.0-or-later
// The JavaScript module (build-web/package) in Node: it reconstructs closed surfaces and curves
// with every method where it applies, gives the command line's triangles for the same points,
// says what the command line says when it refuses, reports progress and cancels.
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { test } from 'node:test';
import { packageDir, requireFile, runNative } from './support.mjs';
import { torus } from './samples.mjs';

requireFile(join(packageDir, 'sculpt.mjs'), 'build the package first (scripts/web)');
const sculpt = await import(join(packageDir, 'sculpt.mjs'));
const { reconstruct, readPoints, methods, version, SculptError } = sculpt;
const scratch = mkdtempSync(join(tmpdir(), 'sculpt-module-'));

function circle(count) {
  const points = new Float64Array(2 * count);
  for (let i = 0; i < count; ++i) {
    points.set([Math.cos(2 * Math.PI * i / count), Math.sin(2 * Math.PI * i / count)], 2 * i);
  }
  return points;
}

function xyz(points, dimension) {
  let text = '';
  for (let i = 0; i < points.length; i += dimension) {
    text += Array.from(points.subarray(i, i + dimension), (x) => x.toPrecision(17)).join(' ') + '\n';
  }
  return text;
}

// The message `sculpt reconstruct` prints for these arguments, without its "sculpt: ".
function nativeRefusal(args, cwd) {
  const run = runNative(['reconstruct', ...args], cwd);
  assert.notEqual(run.status, 0, `the command line accepted ${args.join(' ')}`);
  const line = run.stderr.trim().split('\n').pop();
  assert.match(line, /^sculpt: /);
  return line.slice('sculpt: '.length);
}

test('a closed surface: a torus of genus 1, every sample on it, triangles oriented', () => {
  const points = torus(3000);
  const result = reconstruct(points, { dimension: 3 });
  assert.equal(result.method, 'robust');
  assert.equal(result.verdict.manifold, true, result.verdict.line);
  assert.match(result.verdict.line, /closed 2-manifold of genus 1/);
  assert.equal(result.vertices.length, points.length);
  // A closed surface of genus 1: F = 2V.
  assert.equal(result.triangles.length / 3, 2 * 3000);
  assert.ok(result.triangles.every((index) => index < 3000));
  // Every edge in two triangles, once each way: consistently oriented.
  const directed = new Set();
  for (let t = 0; t < result.triangles.length; t += 3) {
    for (let k = 0; k < 3; ++k) {
      const key = `${result.triangles[t + k]},${result.triangles[t + (k + 1) % 3]}`;
      assert.ok(!directed.has(key), `edge ${key} twice in one direction`);
      directed.add(key);
    }
  }
  assert.equal(result.stats.samples, 3000);
  assert.equal(result.stats.euler_characteristic, 0);
});

test('outliers removed where asked: not on the surface, the others in their order', () => {
  // The torus with three strays far outside it put among its points, after the 1000th.
  const torusPoints = torus(3000);
  const strays = [[2.2, 0.1, 0.3], [0.2, -2.3, 0.1], [-0.1, 0.3, 1.6]];
  const points = new Float64Array(3 * 3003);
  points.set(torusPoints.subarray(0, 3000), 0);
  points.set(torusPoints.subarray(3000), 3 * 1003);
  strays.forEach((stray, k) => points.set(stray, 3 * (1000 + k)));
  const kept = reconstruct(points, { dimension: 3 });  // clean samples: the strays stay
  assert.deepEqual(Array.from(kept.removedOutliers), []);
  assert.equal(kept.vertices.length, points.length);
  const cleaned = reconstruct(points, { dimension: 3, clean: 'outliers' });
  assert.deepEqual(Array.from(cleaned.removedOutliers), [1000, 1001, 1002]);
  assert.deepEqual(cleaned.vertices, torusPoints);
  assert.equal(cleaned.stats.outliers_removed, 3);
  assert.match(cleaned.verdict.line, /closed 2-manifold of genus 1/);
  assert.match(cleaned.verdict.line, /3 outliers removed, not on it/);
});

test('a closed curve in the plane', () => {
  const result = reconstruct(circle(100), { dimension: 2 });
  assert.equal(result.verdict.manifold, true, result.verdict.line);
  assert.equal(result.edges.length, 200);
  assert.equal(result.triangles, undefined);
});

test('every method reconstructs in the dimensions it applies to, and refuses the others', () => {
  assert.equal(methods[0].name, 'robust');
  assert.equal(methods.length, 10);
  const points3 = torus(1500, 11), points2 = circle(80);
  for (const method of methods) {
    for (const [dimension, points] of [[2, points2], [3, points3]]) {
      if (method.dimensions.includes(dimension)) {
        const result = reconstruct(points, { dimension, method: method.name });
        assert.equal(result.method, method.name);
        const facets = dimension === 3 ? result.triangles : result.edges;
        assert.ok(facets.length > 0, `${method.name} ${dimension}D made nothing`);
        assert.equal(result.interpolates, method.interpolates, method.name);
        if (method.interpolates) assert.equal(result.vertices.length, points.length);
      } else {
        assert.throws(() => reconstruct(points, { dimension, method: method.name }), SculptError);
      }
    }
  }
});

test('the triangles of the command line for the same points', () => {
  const points = torus(2000, 3);
  const input = join(scratch, 'torus.xyz'), output = join(scratch, 'torus.off');
  writeFileSync(input, xyz(points, 3));
  for (const method of ['robust', 'paper', 'cocone']) {
    const run = runNative(['reconstruct', input, '--method', method, '-o', output, '--quiet']);
    assert.equal(run.status, 0, run.stderr);
    const lines = readFileSync(output, 'utf8').split('\n').filter((line) => line && !line.startsWith('#'));
    const [vertices, faces] = lines[1].split(/\s+/).map(Number);
    // A triangle as its vertices from the smallest on, in its own order (orientation kept): the
    // C++ libraries' hash maps start triangles at other corners (libstdc++ and libc++).
    const canonical = (corners) => {
      const first = corners.indexOf(Math.min(...corners));
      return [0, 1, 2].map((k) => corners[(first + k) % 3]).join(' ');
    };
    const native = lines.slice(2 + vertices, 2 + vertices + faces)
      .map((line) => canonical(line.trim().split(/\s+/).slice(1).map(Number))).sort();
    const result = reconstruct(points, { dimension: 3, method });
    const ours = [];
    for (let t = 0; t < result.triangles.length; t += 3) {
      ours.push(canonical(Array.from(result.triangles.subarray(t, t + 3))));
    }
    assert.deepEqual(ours.sort(), native, `${method}: the module's triangles differ from the command line's`);
  }
});

test('refusals are SculptErrors with the command line\'s message', () => {
  // Too few points, a method for the other dimension, repeated points.
  const few = join(scratch, 'few.xyz');
  writeFileSync(few, '0 0 0\n1 1 1\n');
  assert.throws(() => reconstruct([0, 0, 0, 1, 1, 1], { dimension: 3 }),
                (error) => error instanceof SculptError &&
                           error.message === nativeRefusal([few, '-o', join(scratch, 'x.stl')]));
  const curve = join(scratch, 'circle.xy');
  writeFileSync(curve, xyz(circle(20), 2));
  assert.throws(() => reconstruct(circle(20), { dimension: 2, method: 'cocone' }),
                { message: nativeRefusal([curve, '--method', 'cocone', '-o', join(scratch, 'x.svg')]) });
  const twice = new Float64Array([...circle(20), 1, 0]);
  const repeated = join(scratch, 'repeated.xy');
  writeFileSync(repeated, xyz(twice, 2));
  assert.throws(() => reconstruct(twice, { dimension: 2 }),
                { message: nativeRefusal([repeated, '-o', join(scratch, 'x.svg')]) });
  assert.equal(reconstruct(twice, { dimension: 2, mergeDuplicates: true }).edges.length, 40);
  // What only JavaScript can get wrong.
  assert.throws(() => reconstruct([0, 0, 1], { dimension: 2 }), SculptError);
  assert.throws(() => reconstruct(circle(10), { dimension: 4 }), SculptError);
  assert.throws(() => reconstruct([0, 0, NaN, 1, 1, 0, 0, 1], { dimension: 2 }), SculptError);
  assert.throws(() => reconstruct(circle(10), { dimension: 2, method: 'nope' }), /no method 'nope'/);
});

test('point files are read as the command line reads them, refused in its words', () => {
  const text = new TextEncoder().encode('# a square\n0 0\n1 0\n1 1\n0 1\n0.5 1.4\n');
  const file = readPoints(text, 'square.xy');
  assert.equal(file.dimension, 2);
  assert.deepEqual(Array.from(file.points), [0, 0, 1, 0, 1, 1, 0, 1, 0.5, 1.4]);
  assert.equal(reconstruct(file.points, { dimension: 2 }).verdict.manifold, true);
  const broken = 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n0 0\n1\n';
  writeFileSync(join(scratch, 'broken.ply'), broken);
  assert.throws(() => readPoints(new TextEncoder().encode(broken), 'broken.ply'),
                { message: nativeRefusal(['broken.ply', '-o', 'x.svg'], scratch) });
});

test('progress fills once and a false from it cancels', () => {
  const seen = [];
  reconstruct(torus(2000), { onProgress: (progress) => { seen.push(progress); } });
  assert.ok(seen.length > 5);
  for (let i = 1; i < seen.length; ++i) assert.ok(seen[i].overall >= seen[i - 1].overall - 1e-9);
  assert.ok(seen.at(-1).overall > 0.9);
  assert.throws(() => reconstruct(torus(2000), { onProgress: () => false }), { message: 'cancelled' });
  // The module works on after a cancel.
  assert.equal(reconstruct(circle(50), { dimension: 2 }).verdict.manifold, true);
});

test('the package: version, types and files', () => {
  const manifest = JSON.parse(readFileSync(join(packageDir, 'package.json'), 'utf8'));
  assert.equal(manifest.version, version);
  assert.equal(manifest.license, 'GPL-3.0-or-later');
  for (const file of manifest.files) requireFile(join(packageDir, file), 'the package is incomplete');
  const types = readFileSync(join(packageDir, 'sculpt.d.ts'), 'utf8');
  for (const name of ['reconstruct', 'readPoints', 'methods', 'version', 'SculptError']) {
    assert.ok(name in sculpt, `the module exports no ${name}`);
    assert.match(types, new RegExp(`export (function|const|class) ${name}\\b`));
  }
});

test('npm pack gives a package that installs and runs in a project of its own', () => {
  const packed = spawnSync('npm', ['pack', packageDir, '--pack-destination', scratch, '--silent'],
                           { encoding: 'utf8' });
  assert.equal(packed.status, 0, packed.stderr);
  const tarball = join(scratch, packed.stdout.trim().split('\n').pop());
  const project = join(scratch, 'project');
  mkdirSync(project);
  writeFileSync(join(project, 'package.json'), '{"name": "user", "version": "1.0.0", "type": "module"}');
  const installed = spawnSync('npm', ['install', tarball, '--no-audit', '--no-fund', '--offline', '--silent'],
                              { cwd: project, encoding: 'utf8' });
  assert.equal(installed.status, 0, installed.stderr);
  writeFileSync(join(project, 'use.mjs'), `
import { reconstruct } from 'sculpt-reconstruction';
const points = [];
for (let i = 0; i < 40; ++i) points.push(Math.cos(i * Math.PI / 20), Math.sin(i * Math.PI / 20));
console.log(reconstruct(points, { dimension: 2 }).verdict.line);
`);
  const used = spawnSync(process.execPath, ['use.mjs'], { cwd: project, encoding: 'utf8' });
  assert.equal(used.status, 0, used.stderr);
  assert.equal(used.stdout.trim(), 'closed curve: 1 component, all 40 samples on it');
});
