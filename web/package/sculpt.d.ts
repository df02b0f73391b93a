// SPDX-License-Identifier: GPL-3.0-or-later
// Types of sculpt.mjs: Sculpt's reconstructions in JavaScript.

/** A failure, in the command line's words (the line `sculpt` prints after "sculpt: "). */
export class SculptError extends Error {
  readonly name: 'SculptError';
}

/** The version of Sculpt this module was built from. */
export const version: string;

export interface MethodInfo {
  /** The name `method` takes: "robust" (the default), "paper", "crust", ... */
  readonly name: string;
  readonly description: string;
  /** The dimensions it reconstructs in. */
  readonly dimensions: ReadonlyArray<2 | 3>;
  /** Whether its result passes through the samples (all but the power crust). */
  readonly interpolates: boolean;
}

/** Every method, the default first. */
export const methods: ReadonlyArray<MethodInfo>;

export interface Progress {
  /** The stage running ("delaunay", "poles", ...). */
  stage: string;
  /** 0..1 within that stage. */
  fraction: number;
  /** 0..1 across the whole reconstruction: a bar that fills once. */
  overall: number;
}

export interface ReconstructOptions {
  /** 2 for a curve in the plane, 3 (the default) for a surface. */
  dimension?: 2 | 3;
  /** One of `methods` (default "robust"). */
  method?: string;
  /** closed, bordered, or automatic (the default: the robust method chooses). */
  kind?: 'automatic' | 'closed' | 'bordered';
  /** Which facets make the surface: auto (default), skin or extraction. */
  rule?: 'auto' | 'skin' | 'extraction';
  /** The alpha shape's radius, in the points' units; 0 (default) chooses it. */
  alpha?: number;
  /** The bounding box's size relative to the samples' (default 5). */
  boxFactor?: number;
  /** Clean the samples first (3D): outliers (remove samples far off their neighbours' surface),
   *  jet (smooth), outliers+jet, none, or auto (the default: both, for robust, where the
   *  measured noise is at least 0.3 of the spacing). The surface then passes through the
   *  cleaned samples, which `vertices` holds; stats.cleaned and stats.outliers_removed say so. */
  clean?: 'auto' | 'none' | 'outliers' | 'jet' | 'outliers+jet';
  /** Drop repeated points instead of refusing them (indices then refer to `vertices`). */
  mergeDuplicates?: boolean;
  /** Called as the stages run; returning false cancels (a SculptError "cancelled"). */
  onProgress?: (progress: Progress) => boolean | void;
}

export interface Verdict {
  /** A closed 2-manifold (closed curves in 2D) or a properly bordered one, every sample on it. */
  manifold: boolean;
  /** One line for people, e.g. "closed 2-manifold of genus 1: 1 component, ...". */
  line: string;
}

export interface Reconstruction {
  dimension: 2 | 3;
  method: string;
  /** 3D: three indices into `vertices` per triangle, oriented outward on a closed surface. */
  triangles?: Uint32Array;
  /** 2D: two indices into `vertices` per edge. */
  edges?: Uint32Array;
  /** The points the indices refer to, `dimension` coordinates each: the samples, or the
   *  power crust's own vertices (`interpolates` false). */
  vertices: Float64Array;
  interpolates: boolean;
  /** The points the cleaning removed as outliers (clean 'outliers', 'outliers+jet', or 'auto'
   *  on noisy points), as indices of the points given, increasing: the surface does not pass
   *  through them, and `vertices` holds the others, in their order. Empty when none was. */
  removedOutliers: Uint32Array;
  verdict: Verdict;
  /** The statistics `sculpt reconstruct --stats` writes: counts, topology, stage timings. */
  stats: Record<string, unknown>;
}

/**
 * Reconstructs a curve (dimension 2) or a surface (dimension 3) from points given as a flat
 * array of coordinates: x0, y0, [z0,] x1, y1, ...
 * @throws SculptError for points it cannot work on, with the command line's message.
 */
export function reconstruct(
  points: Float64Array | ArrayLike<number>,
  options?: ReconstructOptions,
): Reconstruction;

export interface PointFile {
  dimension: 2 | 3;
  /** A flat array, `dimension` coordinates per point. */
  points: Float64Array;
  /** The file and what was done to it, e.g. "scan.ply (3 repeated points dropped)". */
  description: string;
}

/**
 * Reads the points of a point or mesh file (.xyz .pts .txt .csv .pwn .xy .ply .off .obj .stl .las .pcd)
 * with the command line's readers; the name's extension says the format.
 * @throws SculptError for a file they refuse, with the command line's message.
 */
export function readPoints(
  bytes: Uint8Array,
  fileName: string,
  options?: { dimension?: 0 | 2 | 3; mergeDuplicates?: boolean },
): PointFile;

/** An instance of the core's WebAssembly module on a compiled module (for workers). */
export function instantiateCore(compiled: WebAssembly.Module): Promise<unknown>;
