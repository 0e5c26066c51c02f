import type { Grid } from '../core/grid';
import { moveSitesToCentroids, type LloydMove } from '../core/lloydUpdate';
import type { CcvtEngine } from './engine';
import { LloydLoop, type LloydOptions, type MoveSummary } from './lloydLoop';

export type { LloydOptions } from './lloydLoop';
export type { IterationRecord } from '../core/iterationRecord';

/**
 * Lloyd's method on a planar-family grid (plane, tube), one iteration at a time. `sites`
 * (interleaved x, y, texel units) is updated in place.
 */
export class LloydRun extends LloydLoop {
  private readonly move: LloydMove = { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 };
  private readonly summary: MoveSummary = { energy: 0, maxDisplacement: 0, warmFrom: 0 };
  private sums: Float32Array;

  constructor(
    private readonly engine: CcvtEngine,
    private readonly grid: Grid,
    readonly sites: Float32Array,
    options: LloydOptions,
  ) {
    super(engine, options);
    this.sums = engine.sums;
    this.flood();
  }

  protected uploadSites(): void {
    this.engine.setSites(this.sites);
  }

  protected computeSums(): void {
    this.sums = this.engine.computeSums();
  }

  protected moveSites(): MoveSummary {
    const move = moveSitesToCentroids(this.grid, this.sites, this.sums, this.engine.siteCount, this.options.overRelaxation, this.move);
    this.summary.energy = move.energy;
    this.summary.maxDisplacement = move.maxDisplacement;
    this.summary.warmFrom = move.maxDisplacementTexels;
    return this.summary;
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
