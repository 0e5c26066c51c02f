import type { Grid } from '../core/grid';
import { moveSitesToCentroids, type LloydMove } from '../core/lloydUpdate';
import type { CcvtEngine } from './engine';

export interface LloydOptions {
  readonly maxIterations: number;
  /** Stop once the largest site displacement (µm) falls below this; 0 runs every iteration. */
  readonly tolerance: number;
  /** 1 = plain Lloyd; up to ~1.9 over-relaxes. */
  readonly overRelaxation: number;
  /** Start each jump flood from the previous labels instead of from scratch. */
  readonly warmStart: boolean;
  /** Wait for the GPU after each jump flood, so jump flood and centroid times are apart. */
  readonly profile?: boolean;
}

/** One Lloyd iteration as recorded in the result. */
export interface IterationRecord {
  readonly iteration: number;
  /** CVT energy of the sites at the start of the iteration (the Voronoi they were moved in). */
  readonly energy: number;
  /** Largest site displacement of this iteration, µm. */
  readonly maxDisplacement: number;
  /** Jump-flood passes that labelled the sites of this iteration. */
  readonly jumpFloodPasses: number;
  readonly jumpFloodMs: number;
  readonly centroidMs: number;
}

/**
 * Lloyd's method driven one iteration at a time, so a page can yield between iterations
 * and a user can cancel. `sites` (interleaved x, y, texel units) is updated in place.
 */
export class LloydRun {
  readonly iterations: IterationRecord[] = [];
  converged = false;
  private readonly move: LloydMove = { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 };
  private lastFloodMs: number;
  private lastPasses: number;

  constructor(
    private readonly engine: CcvtEngine,
    private readonly grid: Grid,
    readonly sites: Float32Array,
    private readonly options: LloydOptions,
  ) {
    const start = performance.now();
    engine.setSites(sites);
    engine.floodLabels();
    if (options.profile) engine.sync();
    this.lastFloodMs = performance.now() - start;
    this.lastPasses = engine.lastPassCount;
  }

  get done(): boolean {
    return this.converged || this.iterations.length >= this.options.maxIterations;
  }

  /** Centroids of the current labels, move, then label the moved sites. */
  step(): IterationRecord {
    const start = performance.now();
    const sums = this.engine.computeSums();
    const centroidMs = performance.now() - start;
    const move = moveSitesToCentroids(this.grid, this.sites, sums, this.engine.siteCount, this.options.overRelaxation, this.move);
    const record: IterationRecord = {
      iteration: this.iterations.length + 1,
      energy: move.energy,
      maxDisplacement: move.maxDisplacement,
      jumpFloodPasses: this.lastPasses,
      jumpFloodMs: this.lastFloodMs,
      centroidMs,
    };
    this.iterations.push(record);
    if (move.maxDisplacement < this.options.tolerance) this.converged = true;

    const floodStart = performance.now();
    this.engine.setSites(this.sites);
    this.engine.floodLabels(this.options.warmStart ? move.maxDisplacementTexels : undefined);
    if (this.options.profile) this.engine.sync();
    this.lastFloodMs = performance.now() - floodStart;
    this.lastPasses = this.engine.lastPassCount;
    return record;
  }

  /** Energy and empty cells of the final sites (their labels are current in the engine). */
  finish(): { energy: number; emptyCells: number } {
    const sums = this.engine.computeSums();
    let energy = 0;
    let emptyCells = 0;
    for (let i = 0; i < this.engine.siteCount; i++) {
      energy += sums[4 * i + 3];
      if (!(sums[4 * i + 2] > 0)) emptyCells++;
    }
    return { energy: energy * this.grid.texelX * this.grid.texelY, emptyCells };
  }
}
