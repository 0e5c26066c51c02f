import * as THREE from 'three';
import { wrapDelta, type Grid } from '../core/grid';
import centroidGatherFrag from '../shaders/centroidGather.frag';
import fullscreenVert from '../shaders/fullscreen.vert';
import type { TexelLayout } from './layout';
import { ShaderPass } from './shaderPass';
import { createFloatDataTexture, createFloatTarget, readTargetRGBA } from './textures';

/** Side of the window tile one gather draw covers: bounds the loop length per pixel. */
const GATHER_TILE = 48;
/**
 * A window's half-size in radii of a disc of the cell's last area. A regular hexagon's farthest
 * texel is 1.1 such radii from its site; 1.2 (plus the margins below) leaves 0.5-1.5 % of the
 * cells for a retry in a converged loop (1024²-2048², 10,000 sites; 1.1x the pass's time of a
 * test of the ring's own labels alone, which missed slivers), 0.63x the time of the former fixed
 * 1.8-radius windows.
 */
const WINDOW_FACTOR = 1.2;

/**
 * The portable centroid path (no float blending): each site's pixel sums the texels of its own
 * cell inside a square window around the site (see shaders/centroidGather.frag).
 *
 * Windows are per site: radius = 1.2 x the radius of a disc of the cell's last area, + 1 texel,
 * + the largest move since then (at most one disc radius). A cell that reaches its window's
 * ring (comes within a texel of it: shaders/centroidGather.frag) is summed again with a larger
 * window in a retry that skips the finished cells, so a tight guess costs little and a wrong one
 * never costs accuracy. Planar grids only (the cube map has no gather pass: chooseCentroidPath
 * never picks it there).
 */
export class GatherCentroids {
  /** Window half-size per site, texels (negative while retrying: finished). */
  readonly radii: Float32Array;
  private readonly radiusTexture: THREE.DataTexture;
  /** Per site: radius of a disc of the cell's last area (texels). */
  private readonly discRadius: Float32Array;
  private readonly pass: ShaderPass;
  private readonly targets: THREE.WebGLRenderTarget[];
  private readonly largest: number;
  private readonly grid: Grid;
  /** Sites as of the last compute() (stride 4): how far they moved since sizes the windows. */
  private readonly lastSites: Float32Array;
  private first = true;
  /** Ping-pong index of the target the next draw writes. */
  private next = 0;
  /** Draws of the last compute(), retries included (for tests and the benchmark). */
  lastDrawCount = 0;
  /** Windows grown by the last compute() after their cell reached the ring. */
  lastRetries = 0;

  constructor(
    private readonly renderer: THREE.WebGLRenderer,
    layout: TexelLayout,
    private readonly siteCount: number,
    siteTextureWidth: number,
    siteTextureHeight: number,
    /** Prepends the surface preamble and the layout's metric to a shader. */
    program: (body: string) => string,
    uniforms: Record<string, THREE.IUniform>,
  ) {
    if (!layout.grid) throw new Error('the gather centroid path runs on planar grids only');
    const grid = (this.grid = layout.grid);
    this.lastSites = new Float32Array(4 * siteCount);
    this.largest = Math.max(grid.width, grid.height);
    const texels = siteTextureWidth * siteTextureHeight;
    this.radii = new Float32Array(texels);
    this.discRadius = new Float32Array(texels).fill(Math.sqrt((grid.width * grid.height) / (siteCount * Math.PI)));
    this.radiusTexture = createFloatDataTexture(this.radii, siteTextureWidth, siteTextureHeight, THREE.RedFormat);
    // Ping-pong: each window tile adds its part to the previous tile's sums.
    this.targets = [0, 1].map(() => createFloatTarget(siteTextureWidth, siteTextureHeight, THREE.RGBAFormat));
    this.pass = new ShaderPass(
      'triangles',
      fullscreenVert,
      program(centroidGatherFrag),
      {
        ...uniforms,
        labels: { value: null },
        radii: { value: this.radiusTexture },
        previousSums: { value: null },
        firstTile: { value: true },
        siteCount: { value: siteCount },
        maxRadius: { value: 0 },
        tileStart: { value: new THREE.Vector2() },
        tileSize: { value: GATHER_TILE },
      },
      false,
      layout.defines,
    );
  }

  /**
   * Sums (w*dx, w*dy, w, w*d²) per site into `sums` (4 a site). `sites` holds positions with
   * stride 4 (the site texture's data), `weights` the per-texel weight (to measure areas in texels).
   */
  compute(labels: THREE.Texture, sums: Float32Array, sites: Float32Array, weights: Float32Array): Float32Array {
    this.pass.uniforms.labels.value = labels;
    this.sizeWindows(this.movedSinceLast(sites));
    this.lastDrawCount = 0;
    this.lastRetries = 0;
    do {
      readTargetRGBA(this.renderer, this.drawWindows(), sums);
    } while (this.growOverflowingWindows(sums));
    this.measureAreas(sums, sites, weights);
    return sums;
  }

  dispose(): void {
    this.pass.dispose();
    for (const target of this.targets) target.dispose();
    this.radiusTexture.dispose();
  }

  /** Largest distance (texels) any site moved since the last compute(); infinite the first time. */
  private movedSinceLast(sites: Float32Array): number {
    const { width, height, periodicX, periodicY } = this.grid;
    let moved = 0;
    for (let i = 0; i < this.siteCount; i++) {
      const dx = wrapDelta(sites[4 * i] - this.lastSites[4 * i], width, periodicX);
      const dy = wrapDelta(sites[4 * i + 1] - this.lastSites[4 * i + 1], height, periodicY);
      moved = Math.max(moved, dx * dx + dy * dy);
    }
    this.lastSites.set(sites.subarray(0, 4 * this.siteCount));
    const first = this.first;
    this.first = false;
    // NaN-safe: unknown is infinite.
    return first || !(moved >= 0) ? Infinity : Math.sqrt(moved);
  }

  private sizeWindows(movedTexels: number): void {
    for (let i = 0; i < this.siteCount; i++) {
      const disc = this.discRadius[i];
      const radius = Math.ceil(WINDOW_FACTOR * disc + 1 + Math.min(movedTexels, disc));
      this.radii[i] = Math.min(this.largest, radius);
    }
  }

  /** Draws the tiles of the largest window; each pixel only walks its own window's part. */
  private drawWindows(): THREE.WebGLRenderTarget {
    const { uniforms } = this.pass;
    let radius = 0; // the largest window half-size in use (texels)
    for (let i = 0; i < this.siteCount; i++) radius = Math.max(radius, this.radii[i]);
    uniforms.maxRadius.value = radius;
    this.radiusTexture.needsUpdate = true;
    const span = (length: number, periodic: boolean) => (periodic && 2 * radius + 1 >= length ? length : 2 * radius + 1);
    const spanX = span(this.grid.width, this.grid.periodicX);
    const spanY = span(this.grid.height, this.grid.periodicY);
    let first = true;
    for (let ty = 0; ty < spanY; ty += GATHER_TILE) {
      for (let tx = 0; tx < spanX; tx += GATHER_TILE) {
        uniforms.firstTile.value = first;
        uniforms.previousSums.value = this.targets[1 - this.next].texture;
        (uniforms.tileStart.value as THREE.Vector2).set(tx, ty);
        this.pass.draw(this.renderer, this.targets[this.next]);
        this.next = 1 - this.next;
        this.lastDrawCount++;
        first = false;
      }
    }
    return this.targets[1 - this.next];
  }

  /**
   * Grows the windows of flagged cells (weight -1) and marks the others finished (radius -1)
   * for the retry; false when none was flagged.
   */
  private growOverflowingWindows(sums: Float32Array): boolean {
    let flagged = 0;
    for (let i = 0; i < this.siteCount; i++) {
      if (sums[4 * i + 2] >= 0) continue;
      if (this.radii[i] >= this.largest) throw new Error(`gather window of cell ${i} covers the grid but the cell still overflows`);
      this.radii[i] = Math.min(this.largest, Math.ceil(this.radii[i] * 1.5) + 1);
      flagged++;
    }
    if (flagged > 0) {
      for (let i = 0; i < this.siteCount; i++) if (sums[4 * i + 2] >= 0) this.radii[i] = -1;
    }
    this.lastRetries += flagged;
    return flagged > 0;
  }

  /** Each cell's area in texels (~ w / weight at the site) as the radius of a disc. */
  private measureAreas(sums: Float32Array, sites: Float32Array, weights: Float32Array): void {
    const { width, height } = this.grid;
    for (let i = 0; i < this.siteCount; i++) {
      const w = sums[4 * i + 2];
      if (!(w > 0)) continue;
      const x = Math.min(width - 1, Math.floor(sites[4 * i]));
      const y = Math.min(height - 1, Math.floor(sites[4 * i + 1]));
      this.discRadius[i] = Math.sqrt(w / weights[y * width + x] / Math.PI);
    }
  }
}
