#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Lesson 3: a 3D scan to a watertight STL, and the truth about the result.

Reads a point file (or uses the built-in bumpy sphere), drops repeated points, reconstructs with
the default method while showing progress, prints the verdict and the main statistics, and
writes the surface as STL. Exits 1 when the result is not a closed 2-manifold through every
sample: the file is written all the same, but nobody should print it unawares.

    python3 scan_to_stl.py [POINTS] [-o OUTPUT.stl] [--method NAME]
"""
import argparse
import sys

import sculpt


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("points", nargs="?", help="a point file; the bumpy sphere if none")
    parser.add_argument("-o", "--output", default="surface.stl")
    parser.add_argument("--method", default=sculpt.DEFAULT_METHOD, choices=list(sculpt.methods(dimension=3)))
    args = parser.parse_args()

    try:
        points = sculpt.read_points(args.points, dimension=3) if args.points else \
            sculpt.example("bumpy")
        points = sculpt.merge_duplicates(points)

        def progress(stage, fraction):
            print(f"\r  {stage:<20} {100 * fraction:3.0f}%", end="", file=sys.stderr)

        result = sculpt.reconstruct(points, method=args.method, progress=progress)
        print("\r\033[K", end="", file=sys.stderr)
        sculpt.write(result, args.output)
    except sculpt.InputError as error:
        print(f"scan_to_stl: error: {error}", file=sys.stderr)
        return 1

    stats = result.stats
    print(f"{len(points)} points, method {result.method}, {stats['total_seconds']:.2f} s")
    print(f"{stats['facets']} triangles, {stats['components']} component(s), "
          f"Euler characteristic {stats['euler_characteristic']}")
    print(f"wrote {args.output}")
    print(f"verdict: {result.verdict}")
    return 0 if result.manifold else 1


if __name__ == "__main__":
    sys.exit(main())
