// SPDX-License-Identifier: GPL-3.0-or-later
// Points the tests and the benchmark sample for themselves, from a fixed seed, so that every run and
// the command line see the same input.

// A torus of radii 1 and 0.4, sampled uniformly in its two angles: `count` points as x, y, z, ...
export function torus(count, seed = 7) {
  // Park and Miller's minimal standard generator: the same sequence in every JavaScript engine.
  let state = seed;
  const random = () => (state = (state * 48271) % 2147483647) / 2147483647;
  const points = new Float64Array(3 * count);
  for (let i = 0; i < count; ++i) {
    const u = 2 * Math.PI * random(), v = 2 * Math.PI * random();
    points.set([(1 + 0.4 * Math.cos(v)) * Math.cos(u), (1 + 0.4 * Math.cos(v)) * Math.sin(u),
                0.4 * Math.sin(v)], 3 * i);
  }
  return points;
}
