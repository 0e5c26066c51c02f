import * as THREE from 'three';
import type { Grid } from '../core/grid';
import { accumulateCentroidRows } from '../core/labels';
import { FloodSchedules, type JumpFloodVariant } from '../core/jumpSchedule';
import centroidScatterFrag from '../shaders/centroidScatter.frag';
import centroidScatterVert from '../shaders/centroidScatter.vert';
import idSplatFrag from '../shaders/idSplat.frag';
import refreshLabelsFrag from '../shaders/refreshLabels.frag';
import fullscreenVert from '../shaders/fullscreen.vert';
import jumpFloodFrag from '../shaders/jumpFlood.frag';
import labelSplatFrag from '../shaders/labelSplat.frag';
import labelSplatVert from '../shaders/labelSplat.vert';
import { chooseCentroidPath, type CentroidPath, type RequestedCentroidPath } from './centroidPolicy';
import { GpuCapabilityError, type GpuContext } from './context';
import { GatherCentroids } from './gatherCentroids';
import { PackedLabels } from './packedLabels';
import { floodPingPong } from './pingPong';
import { ShaderPass } from './shaderPass';
import { createFloatDataTexture, createFloatTarget, readTargetRGBA } from './textures';

/** "No site" in a label (x < 0) and in an id map or id target (id < 0). */
const EMPTY_LABEL = new Float32Array([-1, -1, -1, 0]);

export type { CentroidPath } from './centroidPolicy';

export interface EngineOptions {
  readonly variant: JumpFloodVariant;
  /** 'auto' and the other choices: see chooseCentroidPath. */
  readonly centroidPath: RequestedCentroidPath;
}

/**
 * The GPU half of Lloyd's method on a planar-family grid: jump flood (labels) and centroid
 * sums. Every texture, target and program is created in the constructor, so the Lloyd loop
 * allocates nothing and compiles nothing. The CPU half (moving sites) is in ./lloyd.
 */
export class CcvtEngine {
  readonly centroidPath: CentroidPath;
  readonly siteTextureWidth: number;
  readonly siteTextureHeight: number;
  /** Sums per site after computeSums(): [w*dx, w*dy, w, w*d²] (texel units, µm²). */
  readonly sums: Float32Array;
  /** The readback path's float64 accumulator (null on the other paths). */
  private readonly readbackSums: Float64Array | null;
  /** Jump-flood passes run by the last floodLabels() call. */
  lastPassCount = 0;

  private readonly renderer: THREE.WebGLRenderer;
  private readonly siteData: Float32Array;
  private readonly siteTexture: THREE.DataTexture;
  private readonly weightTexture: THREE.DataTexture;
  private readonly labelTargets: [THREE.WebGLRenderTarget, THREE.WebGLRenderTarget];
  private current = 0;
  private readonly idMapTarget: THREE.WebGLRenderTarget;
  private readonly sumsTarget: THREE.WebGLRenderTarget;
  private readonly gather: GatherCentroids | null;
  private readonly packedLabels: PackedLabels;
  /** The per-texel weights are all 1 (no setWeights yet): the CPU reduction skips them. */
  private uniformWeights = true;
  private readonly refreshPass: ShaderPass;
  private readonly splatPass: ShaderPass;
  private readonly idSplatPass: ShaderPass;
  private readonly floodPass: ShaderPass;
  private readonly centroidPass: ShaderPass | null;
  private readonly schedules: FloodSchedules;
  private readonly syncPixel = new Float32Array(4);
  /** Largest distance (texels) any site moved since the last computeSums(). */
  private movedSinceSums = Infinity;

  constructor(
    private readonly context: GpuContext,
    readonly grid: Grid,
    readonly siteCount: number,
    private readonly options: EngineOptions,
  ) {
    const { maxTextureSize } = context.capabilities;
    if (grid.width > maxTextureSize || grid.height > maxTextureSize) {
      throw new GpuCapabilityError(
        `resolution: the grid is ${grid.width} x ${grid.height} texels but this GPU allows at most ` + `${maxTextureSize} per side; lower resolution`,
      );
    }
    this.centroidPath = chooseCentroidPath('planar grid', options.centroidPath, context.capabilities).path;
    this.renderer = context.renderer;

    this.siteTextureWidth = Math.min(siteCount, maxTextureSize);
    this.siteTextureHeight = Math.ceil(siteCount / this.siteTextureWidth);
    if (this.siteTextureHeight > maxTextureSize) {
      throw new GpuCapabilityError(`cells: ${siteCount} sites do not fit in a ${maxTextureSize}² texture`);
    }
    this.siteData = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.siteTexture = createFloatDataTexture(this.siteData, this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat);
    this.weightTexture = createFloatDataTexture(new Float32Array(grid.width * grid.height).fill(1), grid.width, grid.height, THREE.RedFormat);
    // Labels: the nearest site's position (RG32F) per texel, flooded; the id map: each site's
    // id at the texel it is splatted to. A texel's site id is its position's entry in the id map
    // (read by the centroid passes and the packed readback; never resolved into a texture).
    this.labelTargets = [createFloatTarget(grid.width, grid.height, THREE.RGFormat), createFloatTarget(grid.width, grid.height, THREE.RGFormat)];
    this.idMapTarget = createFloatTarget(grid.width, grid.height, THREE.RedFormat);
    this.sumsTarget = createFloatTarget(this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat);
    this.sums = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.schedules = new FloodSchedules(grid.width, grid.height, options.variant);

    // Uniform objects are shared between programs: one update reaches all of them.
    const metric = {
      gridSize: { value: new THREE.Vector2(grid.width, grid.height) },
      texelSize: { value: new THREE.Vector2(grid.texelX, grid.texelY) },
      sites: { value: this.siteTexture },
      siteWidth: { value: this.siteTextureWidth },
    };
    const defines = { PERIODIC_X: grid.periodicX ? 1 : 0, PERIODIC_Y: grid.periodicY ? 1 : 0 };
    const labels = { value: this.labelTargets[0].texture as THREE.Texture };
    const idMap = { value: this.idMapTarget.texture };
    const weights = { value: this.weightTexture };
    this.refreshPass = new ShaderPass('triangles', fullscreenVert, refreshLabelsFrag, { ...metric, labels, idMap }, false, defines);
    this.splatPass = new ShaderPass('points', labelSplatVert, labelSplatFrag, { ...metric }, false, defines);
    this.idSplatPass = new ShaderPass('points', labelSplatVert, idSplatFrag, { ...metric }, false, defines);
    this.floodPass = new ShaderPass(
      'triangles',
      fullscreenVert,
      jumpFloodFrag,
      { ...metric, labels, stepSize: { value: 1 }, aspect: { value: grid.texelY / grid.texelX } },
      false,
      defines,
    );
    this.centroidPass =
      this.centroidPath !== 'blend'
        ? null
        : new ShaderPass(
            'points',
            centroidScatterVert,
            centroidScatterFrag,
            { ...metric, labels, idMap, weights, sumsSize: { value: new THREE.Vector2(this.siteTextureWidth, this.siteTextureHeight) } },
            true,
            defines,
          );
    this.gather =
      this.centroidPath === 'gather'
        ? new GatherCentroids(this.renderer, grid, siteCount, this.siteTextureWidth, this.siteTextureHeight, { ...metric, labels, idMap, weights }, defines)
        : null;
    // Used by readLabels on every path; three.js allocates the target on its first use.
    this.packedLabels = new PackedLabels(this.renderer, grid, { ...metric, labels, idMap }, defines);
    this.readbackSums = this.centroidPath === 'readback' ? new Float64Array(4 * siteCount) : null;
  }

  /** Uploads site positions (interleaved x, y in texel units). */
  setSites(sites: ArrayLike<number>): void {
    const data = this.siteData;
    const { width, height, periodicX, periodicY } = this.grid;
    let moved = 0;
    for (let i = 0; i < this.siteCount; i++) {
      let dx = sites[2 * i] - data[4 * i];
      let dy = sites[2 * i + 1] - data[4 * i + 1];
      if (periodicX) dx -= width * Math.round(dx / width);
      if (periodicY) dy -= height * Math.round(dy / height);
      moved = Math.max(moved, dx * dx + dy * dy);
      data[4 * i] = sites[2 * i];
      data[4 * i + 1] = sites[2 * i + 1];
    }
    // Largest move since the last sums (sizes the gather windows); NaN-safe: unknown is infinite.
    this.movedSinceSums += moved >= 0 ? Math.sqrt(moved) : Infinity;
    this.siteTexture.needsUpdate = true;
  }

  /** Uploads the per-texel weight (density x area element), width*height values. */
  setWeights(weights: Float32Array): void {
    if (weights.length !== this.grid.width * this.grid.height) throw new RangeError('weights: wrong size');
    (this.weightTexture.image.data as Float32Array).set(weights);
    this.weightTexture.needsUpdate = true;
    this.uniformWeights = false;
  }

  /**
   * Labels every texel with its nearest site. Cold: from scratch. Warm: from the previous
   * labels, given the largest distance (texels) any site moved since they were computed.
   */
  floodLabels(warmFromDisplacement?: number): void {
    const steps = this.schedules.steps(warmFromDisplacement);
    if (warmFromDisplacement === undefined) {
      this.clearToEmpty(this.labelTargets[this.current]);
    } else {
      // Old positions -> ids (through the id map of the old positions) -> new positions.
      this.refreshPass.uniforms.labels.value = this.labelTargets[this.current].texture;
      this.current = 1 - this.current;
      this.refreshPass.draw(this.renderer, this.labelTargets[this.current]);
    }
    this.clearToEmpty(this.idMapTarget);
    this.idSplatPass.draw(this.renderer, this.idMapTarget, this.siteCount);
    // Splatting on top of old labels makes sure every site owns at least its own texel.
    this.splatPass.draw(this.renderer, this.labelTargets[this.current], this.siteCount);
    this.current = floodPingPong(this.renderer, this.floodPass, this.labelTargets, this.current, steps);
    this.lastPassCount = steps.length;
  }

  /** Clears a label or id target to "no site" with glClear: far cheaper than a pass on software GL. */
  private clearToEmpty(target: THREE.WebGLRenderTarget): void {
    this.renderer.setRenderTarget(target);
    this.context.gl.clearBufferfv(this.context.gl.COLOR, 0, EMPTY_LABEL);
  }

  /** Sums (w*dx, w*dy, w, w*d²) per site over the current labels; result in `this.sums`. */
  computeSums(): Float32Array {
    // Both paths read positions and the id map directly: no resolve pass in the Lloyd loop.
    const labelTexture = this.labelTargets[this.current].texture;
    if (this.gather) {
      const moved = this.movedSinceSums;
      this.movedSinceSums = 0;
      return this.gather.compute(labelTexture, this.sums, this.siteData, this.weightTexture.image.data as Float32Array, moved);
    }
    if (this.readbackSums) {
      this.readbackSums.fill(0);
      this.packedLabels.read(labelTexture, this.accumulateBand);
      this.sums.set(this.readbackSums);
      return this.sums;
    }
    const scatter = this.centroidPass!;
    scatter.uniforms.labels.value = labelTexture;
    this.renderer.setRenderTarget(this.sumsTarget);
    this.renderer.setClearColor(0x000000, 0);
    this.renderer.clear(true, false, false);
    scatter.draw(this.renderer, this.sumsTarget, this.grid.width * this.grid.height);
    return readTargetRGBA(this.renderer, this.sumsTarget, this.sums);
  }

  /** Waits for the GPU (a one-texel readback); used to time passes apart. */
  sync(): void {
    readTargetRGBA(this.renderer, this.labelTargets[this.current], this.syncPixel, 0, 0, 1, 1);
  }

  /** Reads the current labels: one site id (or -1) per texel, row-major. */
  readLabels(out = new Int32Array(this.grid.width * this.grid.height)): Int32Array {
    const { width } = this.grid;
    this.packedLabels.read(this.labelTargets[this.current].texture, (ids, firstRow, rows) => {
      out.set(ids.subarray(0, rows * width), firstRow * width);
    });
    return out;
  }

  /** The readback path's reduction of one band of packed ids (a field: no closure per call). */
  private readonly accumulateBand = (ids: Int32Array, firstRow: number, rows: number): void => {
    const weights = this.uniformWeights ? null : (this.weightTexture.image.data as Float32Array);
    accumulateCentroidRows(this.grid, ids, firstRow, rows, this.siteData, 4, this.siteCount, weights, this.readbackSums!);
  };

  /** The gather path's windows and draws (null on the blend path). */
  get gatherStats(): GatherCentroids | null {
    return this.gather;
  }

  dispose(): void {
    const passes = [this.refreshPass, this.splatPass, this.idSplatPass, this.floodPass, this.centroidPass];
    for (const pass of passes) pass?.dispose();
    for (const target of [...this.labelTargets, this.idMapTarget, this.sumsTarget]) target.dispose();
    this.gather?.dispose();
    this.packedLabels.dispose();
    this.siteTexture.dispose();
    this.weightTexture.dispose();
  }
}
