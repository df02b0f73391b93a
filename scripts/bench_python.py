#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""What calling Sculpt from Python costs over its C++ core (a benchmark, not a test).

For each input, one table row: the core's own time (the sum of its stages, as
`sculpt reconstruct` reports it), the wall time of sculpt.reconstruct() around it in the same
call (numpy conversion, the GIL released and taken back, the result wrapped), and the views of
every stage taken afterwards. Each is the median of several runs.

    PYTHONPATH=build/python python3 scripts/bench_python.py [--points 150000] [--runs 3]
"""
import argparse
import statistics
import time

import numpy as np

import sculpt


def torus(n, rng, major=1.0, minor=0.4):
    """Points on a torus, uniform by area (rejection on the tube angle)."""
    points = []
    while sum(len(p) for p in points) < n:
        u, v, w = rng.random((3, n)) * [[2 * np.pi], [2 * np.pi], [1]]
        keep = w < (major + minor * np.cos(v)) / (major + minor)
        r = major + minor * np.cos(v[keep])
        points.append(np.column_stack([r * np.cos(u[keep]), r * np.sin(u[keep]),
                                       minor * np.sin(v[keep])]))
    return np.concatenate(points)[:n]


def flower(n, rng):
    """A closed curve of n samples at random positions along it (a five-petal flower)."""
    t = np.sort(rng.random(n)) * 2 * np.pi
    r = 1 + 0.3 * np.cos(5 * t)
    return np.column_stack([r * np.cos(t), r * np.sin(t)])


def measure(points, method, runs):
    core, wall, views = [], [], []
    for _ in range(runs):
        start = time.perf_counter()
        result = sculpt.reconstruct(points, method=method)
        wall.append(time.perf_counter() - start)
        core.append(result.stats["total_seconds"])
        start = time.perf_counter()
        for stage in result.stages.values():
            vars(stage)
        views.append(time.perf_counter() - start)
    return statistics.median(core), statistics.median(wall), statistics.median(views), result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=150_000)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    inputs = [(f"torus {args.points}", torus(args.points, rng)),
              (f"flower {args.points}", flower(args.points, rng))]
    print(f"sculpt {sculpt.version()}: Python over the C++ core, median of {args.runs} runs")
    print(f"{'input':<16}{'method':<10}{'core s':>9}{'python s':>10}{'overhead':>10}"
          f"{'views ms':>10}  verdict")
    for name, points in inputs:
        for method in ("robust", "paper"):
            core, wall, views, result = measure(points, method, args.runs)
            print(f"{name:<16}{method:<10}{core:>9.3f}{wall:>10.3f}{100 * (wall / core - 1):>9.1f}%"
                  f"{1000 * views:>10.2f}  {result.verdict}")


if __name__ == "__main__":
    main()
