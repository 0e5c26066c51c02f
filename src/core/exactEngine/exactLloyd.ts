/**
 * Lloyd's method on the exact Voronoi diagram (CPU), for planes and tubes: the exact engine's
 * counterpart of gpu/lloyd.ts's GpuLloydRun, with the same constructor shape, records and stopping
 * rules, so the pipeline drives either one the same way.
 *
 * Per iteration: triangulate the sites (periodic copies, cells clipped at open edges:
 * PlanarVoronoi), integrate the density over every cell exactly (CellIntegrator), then move
 * the sites with the same update the GPU engine uses (moveSitesToCentroids: over-relaxation,
 * wrap on periodic axes, clamp on open ones, float32 storage, displacement measured from the
 * stored value). The per-site sums are laid out as the GPU's [w·dx, w·dy, w, w·d²] in texel
 * units (w in texels of area), so energies match the GPU's definition: Σ∫ρ|x - z|² in µm⁴.
 *
 * The loop reuses every buffer (the triangulation is updated in place); nothing is allocated per
 * iteration except by d3-delaunay when the triangle count grows past what it has.
 */
import type { IterationRecord, LloydIterations } from '../iterationRecord';
import type { Grid } from '../grid';
import { moveSitesToCentroids, type LloydMove } from '../lloydUpdate';
import { CellIntegrator, type ExactDensity } from './cellIntegrals';
import { PlanarVoronoi } from './planarVoronoi';
import { PolygonBuffer } from './polygon';

/** The Lloyd options the exact engine reads (gpu/lloyd.ts's LloydOptions is assignable to it). */
export interface ExactLloydOptions {
  readonly maxIterations: number;
  /** Stop once the largest site displacement (µm) falls below this; 0 runs every iteration. */
  readonly tolerance: number;
  /** 1 = plain Lloyd; up to ~1.9 over-relaxes. */
  readonly overRelaxation: number;
}

/** One iteration: the GPU engine's record (jumpFloodPasses 0; see IterationRecord for the timings). */
export type ExactIterationRecord = IterationRecord;

const UNIFORM: ExactDensity = { kind: 'uniform' };

/** Exact sums per site: [w·dx, w·dy, w, w·d²] (offsets in texels, w in texel areas, d² in µm²). */
export class ExactCentroids {
  readonly voronoi: PlanarVoronoi;
  readonly sums: Float64Array;
  private readonly integrator: CellIntegrator;
  private readonly cell = new PolygonBuffer();
  private readonly moments: Float64Array;
  /** The moments in the diagram's spatial order, as the cells are walked. */
  private readonly spatial: Float64Array;

  constructor(
    readonly grid: Grid,
    readonly count: number,
    density: ExactDensity = UNIFORM,
  ) {
    this.voronoi = new PlanarVoronoi(grid, count);
    this.integrator = new CellIntegrator(grid, density);
    this.sums = new Float64Array(4 * count);
    this.moments = new Float64Array(4 * count);
    this.spatial = new Float64Array(4 * count);
  }

  /** Triangulates the sites (interleaved x, y texel units). */
  build(sites: ArrayLike<number>): void {
    this.voronoi.build(sites);
  }

  /** Integrates every cell of the last build; returns the sums (GPU layout). */
  computeSums(): Float64Array {
    const { grid, count, voronoi, moments, spatial, sums } = this;
    // Again (rarely) when a cell of a site near a periodic seam was not certified (planarVoronoi.ts).
    do {
      spatial.fill(0);
      // Cells in the diagram's spatial order, summed in that order (everything read and written
      // is close in memory), then moved to the sites' order; each cell's sums are its own.
      for (let k = 0; k < count; k++) {
        voronoi.cellAt(k, this.cell);
        this.integrator.integrate(this.cell, voronoi.xAt(k), voronoi.yAt(k), spatial, 4 * k);
      }
    } while (voronoi.retry());
    for (let k = 0; k < count; k++) {
      const i = voronoi.siteAt(k);
      moments[4 * i] = spatial[4 * k];
      moments[4 * i + 1] = spatial[4 * k + 1];
      moments[4 * i + 2] = spatial[4 * k + 2];
      moments[4 * i + 3] = spatial[4 * k + 3];
    }
    const texelArea = grid.texelX * grid.texelY;
    for (let i = 0; i < count; i++) {
      sums[4 * i] = moments[4 * i + 1] / grid.texelX / texelArea;
      sums[4 * i + 1] = moments[4 * i + 2] / grid.texelY / texelArea;
      sums[4 * i + 2] = moments[4 * i] / texelArea;
      sums[4 * i + 3] = moments[4 * i + 3] / texelArea;
    }
    return sums;
  }

  /** ∫ρ|x - z|² over every cell of the last computeSums (µm⁴) and the cells of no weight. */
  energy(): { energy: number; emptyCells: number } {
    let energy = 0;
    let emptyCells = 0;
    for (let i = 0; i < this.count; i++) {
      energy += this.moments[4 * i + 3];
      if (!(this.moments[4 * i] > 0)) emptyCells++;
    }
    return { energy, emptyCells };
  }
}

/**
 * Lloyd's method driven one iteration at a time (like gpu/lloyd.ts's GpuLloydRun; both implement LloydIterations). `sites`
 * (interleaved x, y, texel units, float32 as the GPU engine keeps them) is updated in place.
 */
export class ExactLloydRun implements LloydIterations {
  readonly iterations: ExactIterationRecord[] = [];
  converged = false;
  private readonly centroids: ExactCentroids;
  private readonly move: LloydMove = { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 };

  constructor(
    private readonly grid: Grid,
    readonly sites: Float32Array,
    private readonly options: ExactLloydOptions,
    density: ExactDensity = UNIFORM,
  ) {
    if (sites.length % 2 !== 0) throw new Error(`sites: ${sites.length} values is not a list of (x, y) pairs`);
    if (!(options.overRelaxation > 0 && options.overRelaxation < 2)) {
      throw new Error(`lloyd.overRelaxation must be in (0, 2) (got ${options.overRelaxation})`);
    }
    this.centroids = new ExactCentroids(grid, sites.length / 2, density);
  }

  /** The diagram: after finish(), of the final sites (exactSurface can read it without rebuilding). */
  get voronoi(): PlanarVoronoi {
    return this.centroids.voronoi;
  }

  /** Triangulations done again because a cell near a periodic seam was not certified (PlanarVoronoi). */
  get retries(): number {
    return this.centroids.voronoi.retries;
  }

  get done(): boolean {
    return this.converged || this.iterations.length >= this.options.maxIterations;
  }

  /** Exact diagram and centroids of the current sites, then the move. */
  step(): ExactIterationRecord {
    const start = performance.now();
    this.centroids.build(this.sites);
    const built = performance.now();
    const sums = this.centroids.computeSums();
    const move = moveSitesToCentroids(this.grid, this.sites, sums, this.centroids.count, this.options.overRelaxation, this.move);
    const record: ExactIterationRecord = {
      iteration: this.iterations.length + 1,
      energy: move.energy,
      maxDisplacement: move.maxDisplacement,
      jumpFloodPasses: 0,
      diagramMs: built - start,
      centroidMs: performance.now() - built,
    };
    this.iterations.push(record);
    if (move.maxDisplacement < this.options.tolerance) this.converged = true;
    return record;
  }

  /** Energy (µm⁴) and empty cells of the final sites. */
  finish(): { energy: number; emptyCells: number } {
    this.centroids.build(this.sites);
    this.centroids.computeSums();
    return this.centroids.energy();
  }
}
