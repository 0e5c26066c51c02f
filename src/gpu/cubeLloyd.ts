import { PROJECTION_STRIDE, type ClosedProjector } from '../core/closed/projector';
import { storeProjection, type ClosedSites } from '../core/closed/geometry';
import type { LloydOptions } from './lloyd';
import { LloydLoop, type MoveSummary } from './lloydLoop';
import { CUBE_SUMS_STRIDE, type CubeCcvtEngine } from './cubeEngine';

/**
 * Lloyd's method for a constrained CVT on a closed surface (Du, Gunzburger & Ju 2003), one
 * iteration at a time like LloydRun: GPU labels and sums, then on the CPU each site moves to
 * the closest surface point of its cell's Euclidean centroid (site + ω · mean offset). For
 * ω = 1 the CVT energy Σ w |p - z|² never increases: the constrained centroid minimises each
 * cell's energy over the surface (it equals M |z - c|² + const), and relabelling can only
 * lower it. `sites` is updated in place; the loop allocates nothing.
 */
export class ClosedLloydRun extends LloydLoop {
  private readonly buffer = new Float64Array(PROJECTION_STRIDE);
  private readonly summary: MoveSummary = { energy: 0, maxDisplacement: 0, warmFrom: 0 };

  /**
   * @param texelSpacing smallest distance (µm) between neighbouring texel centres: converts a
   *   displacement into texels for the warm-started flood (an upper bound).
   */
  constructor(
    private readonly engine: CubeCcvtEngine,
    private readonly projector: ClosedProjector,
    readonly sites: ClosedSites,
    options: LloydOptions,
    private readonly texelSpacing: number,
  ) {
    super(engine, options);
    this.flood();
  }

  protected uploadSites(): void {
    this.engine.setSites(this.sites.positions, this.sites.texels);
  }

  protected computeSums(): void {
    this.engine.computeSums();
  }

  protected moveSites(): MoveSummary {
    const { sites, engine, buffer } = this;
    const sums = engine.sums;
    const omega = this.options.overRelaxation;
    let energy = 0;
    let maxSquared = 0;
    for (let i = 0; i < sites.count; i++) {
      const o = CUBE_SUMS_STRIDE * i;
      energy += sums[o + 4];
      const w = sums[o + 3];
      if (!(w > 0)) continue;
      // Offsets were summed against the float32 site the GPU saw.
      const x = engine.siteCoordinate(i, 0) + (omega * sums[o]) / w;
      const y = engine.siteCoordinate(i, 1) + (omega * sums[o + 1]) / w;
      const z = engine.siteCoordinate(i, 2) + (omega * sums[o + 2]) / w;
      this.projector.project(x, y, z, buffer, 0);
      const dx = buffer[0] - sites.positions[3 * i],
        dy = buffer[1] - sites.positions[3 * i + 1],
        dz = buffer[2] - sites.positions[3 * i + 2];
      const d2 = dx * dx + dy * dy + dz * dz;
      if (d2 > maxSquared) maxSquared = d2;
      storeProjection(sites, i, buffer, 0, engine.n);
    }
    const summary = this.summary;
    summary.energy = energy;
    summary.maxDisplacement = Math.sqrt(maxSquared);
    summary.warmFrom = Math.min(engine.n, summary.maxDisplacement / this.texelSpacing);
    return summary;
  }

  /** Energy and empty cells of the final sites (their labels are current in the engine). */
  finish(): { energy: number; emptyCells: number } {
    const sums = this.engine.computeSums();
    let energy = 0;
    let emptyCells = 0;
    for (let i = 0; i < this.sites.count; i++) {
      energy += sums[CUBE_SUMS_STRIDE * i + 4];
      if (!(sums[CUBE_SUMS_STRIDE * i + 3] > 0)) emptyCells++;
    }
    return { energy, emptyCells };
  }
}
