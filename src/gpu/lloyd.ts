import { PROJECTION_STRIDE, type ClosedProjector } from '../core/closed/projector';
import { storeProjection, type ClosedSites } from '../core/closed/geometry';
import type { Grid } from '../core/grid';
import type { LloydConfig } from '../core/config';
import type { IterationRecord, LloydIterations } from '../core/iterationRecord';
import { moveSitesToCentroids, type LloydMove } from '../core/lloydUpdate';
import { SUMS_STRIDE, type GpuEngine } from './engine';

export type { IterationRecord } from '../core/iterationRecord';

/** Lloyd's settings (the config's `lloyd` section), and `profile`: wait for the GPU after each flood, so flood and centroid times are apart. */
export type LloydOptions = LloydConfig & { readonly profile?: boolean };

/** The CPU half of Lloyd's method on one surface family: the sites, how they upload and move. */
export interface SiteMover<Sites = unknown> {
  readonly sites: Sites;
  upload(engine: GpuEngine): void;
  /**
   * Moves every site to (towards, with over-relaxation ω) its cell's centroid, from engine.sums;
   * `move.maxDisplacementTexels` bounds the move in texels, where a warm-started flood starts.
   */
  move(engine: GpuEngine, omega: number, move: LloydMove): void;
}

/** Sites on a planar-family grid (interleaved x, y, texel units; updated in place). */
export function gridSites(grid: Grid, sites: Float32Array): SiteMover<Float32Array> {
  return {
    sites,
    upload: (engine) => engine.setSites(sites),
    move: (engine, omega, move) => moveSitesToCentroids(grid, sites, engine.sums, engine.siteCount, omega, move, SUMS_STRIDE),
  };
}

/**
 * Sites on a closed surface (Du, Gunzburger & Ju 2003's constrained CVT): each moves to the
 * closest surface point of its cell's Euclidean centroid (site + ω · mean offset). For ω = 1 the
 * CVT energy Σ w |p - z|² never increases: the constrained centroid minimises each cell's
 * energy over the surface (it equals M |z - c|² + const), and relabelling can only lower it.
 * `texelSpacing` (µm, the smallest distance between neighbouring texel centres) converts a
 * displacement into texels for the warm-started flood (an upper bound).
 */
export function closedSites(projector: ClosedProjector, sites: ClosedSites, texelSpacing: number): SiteMover<ClosedSites> {
  const buffer = new Float64Array(PROJECTION_STRIDE);
  return {
    sites,
    upload: (engine) => engine.setSites(sites.positions, sites.texels),
    move(engine, omega, move) {
      const sums = engine.sums;
      let energy = 0;
      let maxSquared = 0;
      for (let i = 0; i < sites.count; i++) {
        const o = SUMS_STRIDE * i;
        energy += sums[o + 4];
        const w = sums[o + 3];
        if (!(w > 0)) continue;
        // Offsets were summed against the float32 site the GPU saw.
        const x = engine.siteCoordinate(i, 0) + (omega * sums[o]) / w;
        const y = engine.siteCoordinate(i, 1) + (omega * sums[o + 1]) / w;
        projector.project(x, y, engine.siteCoordinate(i, 2) + (omega * sums[o + 2]) / w, buffer, 0);
        const dx = buffer[0] - sites.positions[3 * i],
          dy = buffer[1] - sites.positions[3 * i + 1],
          dz = buffer[2] - sites.positions[3 * i + 2];
        maxSquared = Math.max(maxSquared, dx * dx + dy * dy + dz * dz);
        storeProjection(sites, i, buffer, engine.layout.width);
      }
      move.energy = energy;
      move.maxDisplacement = Math.sqrt(maxSquared);
      move.maxDisplacementTexels = Math.min(engine.layout.width, move.maxDisplacement / texelSpacing);
    },
  };
}

/**
 * Lloyd's method on the GPU engine, one iteration at a time: sums of the current labels on the
 * GPU, the sites' move on the CPU (the surface family's SiteMover), then a flood of the moved
 * sites (warm-started from the previous labels if asked), timed apart when profiling. The
 * first flood runs in the constructor.
 */
export class GpuLloydRun<Sites = unknown> implements LloydIterations {
  readonly iterations: IterationRecord[] = [];
  converged = false;
  private readonly move: LloydMove = { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 };
  private lastFloodMs = 0;
  private lastPasses = 0;

  constructor(
    private readonly engine: GpuEngine,
    private readonly mover: SiteMover<Sites>,
    private readonly options: LloydOptions,
  ) {
    this.flood();
  }

  /** The sites, moved in place by each step. */
  get sites(): Sites {
    return this.mover.sites;
  }

  get done(): boolean {
    return this.converged || this.iterations.length >= this.options.maxIterations;
  }

  step(): IterationRecord {
    const start = performance.now();
    this.engine.computeSums();
    const centroidMs = performance.now() - start;
    const move = this.move;
    this.mover.move(this.engine, this.options.overRelaxation, move);
    const record: IterationRecord = {
      iteration: this.iterations.length + 1,
      energy: move.energy,
      maxDisplacement: move.maxDisplacement,
      jumpFloodPasses: this.lastPasses,
      diagramMs: this.lastFloodMs,
      centroidMs,
    };
    this.iterations.push(record);
    if (move.maxDisplacement < this.options.tolerance) this.converged = true;
    this.flood(this.options.warmStart ? move.maxDisplacementTexels : undefined);
    return record;
  }

  /** Energy and empty cells of the final sites (their labels are current in the engine). */
  finish(): { energy: number; emptyCells: number } {
    const sums = this.engine.computeSums();
    let energy = 0;
    let emptyCells = 0;
    for (let i = 0; i < this.engine.siteCount; i++) {
      energy += sums[SUMS_STRIDE * i + 4];
      if (!(sums[SUMS_STRIDE * i + 3] > 0)) emptyCells++;
    }
    return { energy: energy * this.engine.layout.energyScale, emptyCells };
  }

  private flood(warmFrom?: number): void {
    const start = performance.now();
    this.mover.upload(this.engine);
    this.engine.floodLabels(warmFrom);
    if (this.options.profile) this.engine.sync();
    this.lastFloodMs = performance.now() - start;
    this.lastPasses = this.engine.lastPassCount;
  }
}
