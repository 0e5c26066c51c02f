/** One Lloyd iteration as recorded in the result, whichever engine ran it. */
export interface IterationRecord {
  readonly iteration: number;
  /** CVT energy Σ∫ρ|x - z|² (µm⁴ × relative density) of the sites at the start of the iteration (the Voronoi they were moved in). */
  readonly energy: number;
  /** Largest site displacement of this iteration, µm. */
  readonly maxDisplacement: number;
  /** Jump-flood passes that labelled the sites of this iteration (0 for the exact engine). */
  readonly jumpFloodPasses: number;
  /** Building the Voronoi diagram of the iteration's sites, ms: GPU, the jump flood; exact engine, triangulating and walking the cells. */
  readonly diagramMs: number;
  /** GPU: the centroid sums, ms; exact engine: integrating the cells and moving the sites, ms. */
  readonly centroidMs: number;
}

/**
 * Lloyd's method driven one iteration at a time, so a page can yield between iterations and a
 * user can cancel: the one interface the GPU engine's loop (gpu/lloyd.ts) and the exact
 * engine's (exactEngine/exactLloyd.ts) implement.
 */
export interface LloydIterations {
  readonly done: boolean;
  readonly converged: boolean;
  readonly iterations: IterationRecord[];
  /** Centroids of the current sites' cells, then the move. */
  step(): IterationRecord;
  /** CVT energy (µm⁴ x density) and empty cells of the final sites. */
  finish(): { energy: number; emptyCells: number };
}
