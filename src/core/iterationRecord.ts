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
