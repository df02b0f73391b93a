// SPDX-License-Identifier: GPL-3.0-or-later
// Sculpt's reconstructions in JavaScript, in Node and in browsers: the same C++ core as the
// command line (src/web/core_module.cpp), compiled to WebAssembly (sculpt-core.wasm). Importing
// this module loads it; every function after that is synchronous. Errors are SculptError, whose
// message is the line `sculpt` prints after "sculpt: ".
import createSculptCore from './sculpt-core.mjs';

const inNode = typeof process === 'object' && typeof process.versions?.node === 'string';

// The compiled WebAssembly module: read from disk in Node, fetched (and compiled while it
// arrives) in a browser. Emscripten's own loader is not used for this: in an ES module under
// Node, or in a module worker, it finds neither.
async function compileCore() {
  const url = new URL('./sculpt-core.wasm', import.meta.url);
  if (inNode) {
    const { readFile } = await import('node:fs/promises');
    return WebAssembly.compile(await readFile(url));
  }
  try {
    return await WebAssembly.compileStreaming(fetch(url));
  } catch {
    // A server that does not say application/wasm: compile the bytes instead.
    const response = await fetch(url);
    if (!response.ok) throw new Error(`cannot load ${url}: ${response.status}`);
    return WebAssembly.compile(await response.arrayBuffer());
  }
}

// An instance of the core on a compiled module (a worker can make its own from a module the
// page compiled once).
export async function instantiateCore(compiled) {
  return createSculptCore({
    instantiateWasm(imports, receive) {
      WebAssembly.instantiate(compiled, imports).then((instance) => receive(instance, compiled));
      return {};
    },
    print: (line) => console.log(line),
    printErr: (line) => console.warn(line),
  });
}

const core = await instantiateCore(await compileCore());

/** A failure, in the command line's words (e.g. "error: 2 points are too few ..."). */
export class SculptError extends Error {
  constructor(message) {
    super(message);
    this.name = 'SculptError';
  }
}

/** The version of Sculpt this module was built from. */
export const version = core.UTF8ToString(core._sculpt_version());

/** The methods, the default first: {name, description, dimensions, interpolates}. */
export const methods = Object.freeze(JSON.parse(core.UTF8ToString(core._sculpt_methods())));

// Calls a core function that returns a result; reads what `take` wants of it, then frees it.
function withResult(result, take) {
  try {
    const error = core.UTF8ToString(core._sculpt_result_error(result));
    if (error) throw new SculptError(error);
    return take(result);
  } finally {
    core._sculpt_result_free(result);
  }
}

function resultJson(result) {
  return JSON.parse(core.UTF8ToString(core._sculpt_result_json(result)));
}

function resultCoordinates(result) {
  const count = core._sculpt_result_coordinate_count(result);
  const at = core._sculpt_result_coordinates(result) / 8;
  return core.HEAPF64.slice(at, at + count);
}

function withString(text, use) {
  const pointer = core.allocateUTF8(text);
  try {
    return use(pointer);
  } finally {
    core._free(pointer);
  }
}

function checkedOptions(options) {
  if (options === null || typeof options !== 'object') {
    throw new SculptError('error: the options must be an object');
  }
  const { onProgress, dimension = 3, ...rest } = options;
  if (dimension !== 2 && dimension !== 3) {
    throw new SculptError(`error: the dimension must be 2 or 3, not ${dimension}`);
  }
  if (onProgress !== undefined && typeof onProgress !== 'function') {
    throw new SculptError('error: onProgress must be a function');
  }
  return { dimension, onProgress, rest };
}

/**
 * Reconstructs a curve (dimension 2) or a surface (dimension 3) from points given as a flat
 * array of coordinates (x0, y0, [z0,] x1, ...). Returns the edges (2D) or triangles (3D) as
 * indices into `vertices`, the verdict and the statistics.
 */
export function reconstruct(points, options = {}) {
  const { dimension, onProgress, rest } = checkedOptions(options);
  const coordinates = points instanceof Float64Array ? points : Float64Array.from(points ?? []);
  if (coordinates.length % dimension !== 0) {
    throw new SculptError(
      `error: ${coordinates.length} coordinates are not whole ${dimension}D points`);
  }
  for (const value of coordinates) {
    if (!Number.isFinite(value)) throw new SculptError('error: a coordinate is not a finite number');
  }
  const count = coordinates.length / dimension;
  const memory = core._malloc(Math.max(8, coordinates.byteLength));
  if (!memory) throw new SculptError('error: out of memory');
  core.onProgress = onProgress
    ? (stage, fraction, overall) => onProgress({ stage, fraction, overall }) !== false
    : null;
  try {
    core.HEAPF64.set(coordinates, memory / 8);
    const result = withString(JSON.stringify(rest), (optionsText) =>
      core._sculpt_reconstruct(memory, count, dimension, optionsText));
    return withResult(result, () => {
      const { verdict, stats, interpolates, removedOutliers } = resultJson(result);
      const indices = core._sculpt_result_facet_indices(result);
      const at = core._sculpt_result_facets(result) / 4;
      const facets = core.HEAPU32.slice(at, at + indices);
      return {
        dimension,
        method: stats.method,
        [dimension === 3 ? 'triangles' : 'edges']: facets,
        vertices: resultCoordinates(result),
        interpolates,
        removedOutliers: Uint32Array.from(removedOutliers),
        verdict,
        stats,
      };
    });
  } finally {
    core.onProgress = null;
    core._free(memory);
  }
}

/**
 * Reads the points of a point or mesh file (.xyz .ply .off .obj .stl .xy ...) with the command
 * line's readers: {dimension, points (a flat Float64Array), description}.
 */
export function readPoints(bytes, fileName, { dimension = 0, mergeDuplicates = false } = {}) {
  if (!(bytes instanceof Uint8Array)) throw new SculptError('error: the file must be a Uint8Array');
  // Read in a folder of its own, by its name alone: messages name the file as the user does.
  const name = String(fileName ?? '').replace(/[/\\]/g, '_') || 'points.xyz';
  const path = `/read/${name}`;
  core.FS.mkdirTree('/read');
  core.FS.chdir('/read');
  core.FS.writeFile(path, bytes);
  try {
    const result = withString(name, (pathText) =>
      core._sculpt_read_points(pathText, dimension, mergeDuplicates ? 1 : 0));
    return withResult(result, () => {
      const { dimension: read, description } = resultJson(result);
      return { dimension: read, points: resultCoordinates(result), description };
    });
  } finally {
    core.FS.unlink(path);
  }
}
