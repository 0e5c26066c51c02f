import * as THREE from 'three';
import type { Grid } from '../core/grid';
import centroidGatherFrag from '../shaders/centroidGather.frag';
import fullscreenVert from '../shaders/fullscreen.vert';
import { ShaderPass } from './shaderPass';
import { createFloatDataTexture, createFloatTarget, readTargetRGBA } from './textures';

/** Side of the window tile one gather draw covers: bounds the loop length per pixel. */
const GATHER_TILE = 48;

/**
 * The portable centroid path (no float blending): each site's pixel sums the texels of its own
 * cell inside a square window around the site (see shaders/centroidGather.frag). Windows are
 * per site, sized from the cell's last area, so the work stays a small multiple of the grid;
 * a cell that reaches its window's ring is flagged and summed again with a larger window.
 */
export class GatherCentroids {
  /** Window half-size per site, texels. */
  readonly radii: Float32Array;
  private readonly radiusTexture: THREE.DataTexture;
  private readonly pass: ShaderPass;
  private readonly targets: THREE.WebGLRenderTarget[];
  private readonly largest: number;

  constructor(
    private readonly renderer: THREE.WebGLRenderer,
    private readonly grid: Grid,
    private readonly siteCount: number,
    siteTextureWidth: number,
    siteTextureHeight: number,
    uniforms: Record<string, THREE.IUniform>,
    defines: Record<string, number>,
  ) {
    this.largest = Math.max(grid.width, grid.height);
    this.radii = new Float32Array(siteTextureWidth * siteTextureHeight).fill(
      Math.min(this.largest, Math.ceil(2.5 * Math.sqrt((grid.width * grid.height) / siteCount))),
    );
    this.radiusTexture = createFloatDataTexture(this.radii, siteTextureWidth, siteTextureHeight, THREE.RedFormat);
    // Ping-pong: each window tile adds its part to the previous tile's sums.
    this.targets = [0, 1].map(() => createFloatTarget(siteTextureWidth, siteTextureHeight, THREE.RGBAFormat));
    this.pass = new ShaderPass(
      'triangles',
      fullscreenVert,
      centroidGatherFrag,
      {
        ...uniforms,
        radii: { value: this.radiusTexture },
        previousSums: { value: null },
        firstTile: { value: true },
        siteCount: { value: siteCount },
        maxRadius: { value: 0 },
        tileStart: { value: new THREE.Vector2() },
        tileSize: { value: GATHER_TILE },
      },
      false,
      defines,
    );
  }

  /**
   * Sums (w*dx, w*dy, w, w*d²) per site into `sums`. `sites` holds positions with stride 4
   * (the site texture's data) and `weights` the per-texel weight, to size the next windows.
   */
  compute(labels: THREE.Texture, sums: Float32Array, sites: Float32Array, weights: Float32Array): Float32Array {
    this.pass.uniforms.labels.value = labels;
    for (;;) {
      readTargetRGBA(this.renderer, this.drawWindows(), sums);
      if (!this.growOverflowingWindows(sums)) break;
    }
    this.sizeNextWindows(sums, sites, weights);
    return sums;
  }

  /** The largest window half-size in use (texels). */
  get maxRadius(): number {
    let max = 0;
    for (let i = 0; i < this.siteCount; i++) max = Math.max(max, this.radii[i]);
    return max;
  }

  dispose(): void {
    this.pass.dispose();
    for (const target of this.targets) target.dispose();
    this.radiusTexture.dispose();
  }

  /** Draws the tiles of the largest window; each pixel only walks its own window's part. */
  private drawWindows(): THREE.WebGLRenderTarget {
    const { uniforms } = this.pass;
    const radius = this.maxRadius;
    uniforms.maxRadius.value = radius;
    this.radiusTexture.needsUpdate = true;
    const span = (length: number, periodic: boolean) => (periodic && 2 * radius + 1 >= length ? length : 2 * radius + 1);
    const spanX = span(this.grid.width, this.grid.periodicX);
    const spanY = span(this.grid.height, this.grid.periodicY);
    let index = 0;
    let first = true;
    for (let ty = 0; ty < spanY; ty += GATHER_TILE) {
      for (let tx = 0; tx < spanX; tx += GATHER_TILE) {
        uniforms.firstTile.value = first;
        uniforms.previousSums.value = this.targets[1 - index].texture;
        (uniforms.tileStart.value as THREE.Vector2).set(tx, ty);
        this.pass.draw(this.renderer, this.targets[index]);
        index = 1 - index;
        first = false;
      }
    }
    return this.targets[1 - index];
  }

  /** Grows the windows of flagged cells (weight -1); false when none was flagged. */
  private growOverflowingWindows(sums: Float32Array): boolean {
    let grown = false;
    for (let i = 0; i < this.siteCount; i++) {
      if (sums[4 * i + 2] >= 0) continue;
      if (this.radii[i] >= this.largest) throw new Error(`gather window of cell ${i} covers the grid but the cell still overflows`);
      this.radii[i] = Math.min(this.largest, Math.ceil(this.radii[i] * 1.5));
      grown = true;
    }
    return grown;
  }

  /**
   * Next windows from this iteration's cells: texel count ~ w / weight at the site, radius
   * ~ 1.8 x that of a disc of the same area, plus 2 texels for the move. Only a guess: the ring
   * check makes a wrong guess cost time, never accuracy.
   */
  private sizeNextWindows(sums: Float32Array, sites: Float32Array, weights: Float32Array): void {
    const { width, height } = this.grid;
    for (let i = 0; i < this.siteCount; i++) {
      const w = sums[4 * i + 2];
      if (!(w > 0)) continue;
      const x = Math.min(width - 1, Math.floor(sites[4 * i]));
      const y = Math.min(height - 1, Math.floor(sites[4 * i + 1]));
      const texels = w / weights[y * width + x];
      this.radii[i] = Math.min(this.largest, Math.ceil(1.8 * Math.sqrt(texels / Math.PI)) + 2);
    }
  }
}
