import type { IterationRecord } from '../core/iterationRecord';

/** Lloyd's settings, as the config's `lloyd` section gives them. */
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

/** What a Lloyd loop asks of a GPU engine besides its own sums. */
export interface FloodingEngine {
  /** Labels every texel with its nearest site: cold, or warm from a displacement bound. */
  floodLabels(warmFrom?: number): void;
  /** Waits for the GPU (a one-texel readback). */
  sync(): void;
  /** Jump-flood passes the last floodLabels ran. */
  readonly lastPassCount: number;
}

/** A Lloyd move as a loop reports it (a reused object: the loop allocates nothing for it). */
export interface MoveSummary {
  /** CVT energy of the sites before the move. */
  energy: number;
  /** Largest site displacement, µm. */
  maxDisplacement: number;
  /** How far (texels, an upper bound) any site moved: where a warm-started flood starts. */
  warmFrom: number;
}

/**
 * Lloyd's method driven one iteration at a time, so a page can yield between iterations and a
 * user can cancel: sums of the current labels on the GPU, a move on the CPU (the subclass's,
 * one per surface family), then a flood of the moved sites, timed apart when profiling.
 */
export abstract class LloydLoop {
  readonly iterations: IterationRecord[] = [];
  converged = false;
  private lastFloodMs = 0;
  private lastPasses = 0;

  protected constructor(
    private readonly floodingEngine: FloodingEngine,
    protected readonly options: LloydOptions,
  ) {}

  get done(): boolean {
    return this.converged || this.iterations.length >= this.options.maxIterations;
  }

  /** Centroids of the current labels, move, then label the moved sites. */
  step(): IterationRecord {
    const start = performance.now();
    this.computeSums();
    const centroidMs = performance.now() - start;
    const move = this.moveSites();
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
    this.flood(this.options.warmStart ? move.warmFrom : undefined);
    return record;
  }

  /** Uploads the sites and labels them; subclasses call it once from their constructor. */
  protected flood(warmFrom?: number): void {
    const start = performance.now();
    this.uploadSites();
    this.floodingEngine.floodLabels(warmFrom);
    if (this.options.profile) this.floodingEngine.sync();
    this.lastFloodMs = performance.now() - start;
    this.lastPasses = this.floodingEngine.lastPassCount;
  }

  protected abstract uploadSites(): void;
  /** Per-site sums over the current labels, kept by the engine for moveSites. */
  protected abstract computeSums(): void;
  /** Moves every site to (towards, with over-relaxation) its cell's centroid. */
  protected abstract moveSites(): MoveSummary;
}
