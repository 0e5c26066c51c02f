import * as THREE from 'three';
import { FloodSchedules, type JumpFloodVariant } from '../core/jumpSchedule';
import centroidScatterVert from '../shaders/centroidScatter.vert';
import fullscreenVert from '../shaders/fullscreen.vert';
import jumpFloodFrag from '../shaders/jumpFlood.frag';
import packIdsFrag from '../shaders/packIds.frag';
import pointFrag from '../shaders/point.frag';
import refreshLabelsFrag from '../shaders/refreshLabels.frag';
import splatVert from '../shaders/splat.vert';
import surfaceGlsl from '../shaders/surface.glsl';
import { chooseCentroidPath, type CentroidPath, type RequestedCentroidPath } from './centroidPolicy';
import { GpuCapabilityError, type GpuContext } from './context';
import { GatherCentroids } from './gatherCentroids';
import { SUMS_STRIDE, type TexelLayout } from './layout';
import { PackedLabels } from './packedLabels';
import { ShaderPass } from './shaderPass';
import { createFloatDataTexture, createFloatTarget, readTargetRGBA } from './textures';

/** "No site" in a label: id (w) < 0. */
const EMPTY_LABEL = new Float32Array([0, 0, 0, -1]);

export type { CentroidPath } from './centroidPolicy';
export { SUMS_STRIDE } from './layout';

export interface EngineOptions {
  readonly variant: JumpFloodVariant;
  /** 'auto' and the other choices: see chooseCentroidPath. */
  readonly centroidPath: RequestedCentroidPath;
}

/**
 * The GPU half of Lloyd's method on any surface's geometry image (a TexelLayout: planar grid
 * or cube map): splat, jump flood, centroid sums, readback. Every pass is one program, the
 * layout's metric chunk compiled in with its defines. Labels (RGBA32F) are each texel's
 * nearest site's coordinates and id (shaders/surface.glsl); ties go to the smaller id. The
 * geometry (per-texel weight, and point on a cube map) can be replaced (setGeometry), so one
 * engine labels every surface of a stack. Every texture, target and program is created in the
 * constructor: the Lloyd loop allocates nothing and compiles nothing. The CPU half (moving
 * sites) is in ./lloyd.
 */
export class GpuEngine {
  readonly centroidPath: CentroidPath;
  readonly siteTextureWidth: number;
  readonly siteTextureHeight: number;
  /** Per site after computeSums(): SUMS_STRIDE values (float64). */
  readonly sums: Float64Array;
  /** Jump-flood passes run by the last floodLabels() call. */
  lastPassCount = 0;

  private readonly renderer: THREE.WebGLRenderer;
  private readonly siteData: Float32Array;
  private readonly siteTexture: THREE.DataTexture;
  private readonly geometryData: Float32Array;
  private readonly geometryTexture: THREE.DataTexture;
  private readonly labelTargets: [THREE.WebGLRenderTarget, THREE.WebGLRenderTarget];
  private current = 0;
  private readonly sumsTarget: THREE.WebGLRenderTarget;
  private readonly staging: Float32Array;
  private readonly gather: GatherCentroids | null;
  private readonly packedLabels: PackedLabels;
  /** The weights are all 1 (a grid before any setGeometry): the CPU reduction skips them. */
  private uniformWeights: boolean;
  private readonly refreshPass: ShaderPass;
  private readonly splatPass: ShaderPass;
  private readonly floodPass: ShaderPass;
  private readonly scatterPass: ShaderPass | null;
  private readonly schedules: FloodSchedules;

  constructor(
    private readonly context: GpuContext,
    readonly layout: TexelLayout,
    readonly siteCount: number,
    options: EngineOptions,
  ) {
    const { maxTextureSize } = context.capabilities;
    const tooLarge = layout.tooLarge(maxTextureSize);
    if (tooLarge) throw new GpuCapabilityError(tooLarge);
    this.centroidPath = chooseCentroidPath(layout.family, options.centroidPath, context.capabilities).path;
    this.renderer = context.renderer;
    const { width, height } = layout;

    this.siteTextureWidth = Math.min(siteCount, maxTextureSize);
    this.siteTextureHeight = Math.ceil(siteCount / this.siteTextureWidth);
    if (this.siteTextureHeight > maxTextureSize) throw new GpuCapabilityError(`cells: ${siteCount} sites do not fit in a ${maxTextureSize}² texture`);
    this.siteData = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.siteTexture = createFloatDataTexture(this.siteData, this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat);
    this.uniformWeights = layout.geometryChannels === 1;
    this.geometryData = new Float32Array(width * height * layout.geometryChannels).fill(this.uniformWeights ? 1 : 0);
    this.geometryTexture = createFloatDataTexture(this.geometryData, width, height, this.uniformWeights ? THREE.RedFormat : THREE.RGBAFormat);
    this.labelTargets = [createFloatTarget(width, height, THREE.RGBAFormat), createFloatTarget(width, height, THREE.RGBAFormat)];
    this.sumsTarget = createFloatTarget(this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat);
    this.staging = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.sums = new Float64Array(SUMS_STRIDE * siteCount);
    this.schedules = new FloodSchedules(layout.floodWidth, layout.floodHeight, options.variant);

    // Uniform objects are shared between programs: one update reaches all of them.
    const surface = {
      ...layout.uniforms,
      atlasSize: { value: new THREE.Vector2(width, height) },
      sites: { value: this.siteTexture },
      siteWidth: { value: this.siteTextureWidth },
      geometry: { value: this.geometryTexture },
    };
    const labels = { value: this.labelTargets[0].texture as THREE.Texture };
    const program = (body: string) => surfaceGlsl + layout.metric + body;
    const pass = (kind: 'triangles' | 'points', vertex: string, fragment: string, uniforms: Record<string, THREE.IUniform> = {}, blend = false) =>
      new ShaderPass(kind, kind === 'points' ? program(vertex) : vertex, program(fragment), { ...surface, labels, ...uniforms }, blend, layout.defines);
    this.refreshPass = pass('triangles', fullscreenVert, refreshLabelsFrag);
    this.splatPass = pass('points', splatVert, pointFrag);
    this.floodPass = pass('triangles', fullscreenVert, jumpFloodFrag, { stepSize: { value: 1 } });
    const sumsSize = { value: new THREE.Vector2(this.siteTextureWidth, this.siteTextureHeight) };
    this.scatterPass = this.centroidPath === 'blend' ? pass('points', centroidScatterVert, pointFrag, { sumsSize, energyPass: { value: false } }, true) : null;
    this.gather =
      this.centroidPath === 'gather'
        ? new GatherCentroids(this.renderer, layout, siteCount, this.siteTextureWidth, this.siteTextureHeight, program, surface)
        : null;
    this.packedLabels = new PackedLabels(this.renderer, layout, pass('triangles', fullscreenVert, packIdsFrag));
  }

  /**
   * Uploads the surface the next floods run on: the weight per texel (density x area element,
   * width*height values) and, on a cube map, the point per texel (xyz, 3 x width*height, atlas order).
   */
  setGeometry(weight: ArrayLike<number>, points?: ArrayLike<number>): void {
    const count = this.layout.width * this.layout.height;
    const channels = this.layout.geometryChannels;
    if (weight.length !== count || (channels === 4 && points?.length !== 3 * count)) throw new RangeError('setGeometry: wrong size');
    const data = this.geometryData;
    for (let k = 0; k < count; k++) {
      if (channels === 4) for (let c = 0; c < 3; c++) data[4 * k + c] = points![3 * k + c];
      data[channels * k + channels - 1] = weight[k];
    }
    this.geometryTexture.needsUpdate = true;
    this.uniformWeights = false;
  }

  /**
   * Uploads sites: `dimensions` coordinates per site (grid: x, y in texel units; cube map: xyz
   * in µm) and, on a cube map, the atlas index of the texel each lies in.
   */
  setSites(coordinates: ArrayLike<number>, texels?: ArrayLike<number>): void {
    const data = this.siteData;
    const dims = this.layout.dimensions;
    for (let i = 0; i < this.siteCount; i++) {
      for (let c = 0; c < dims; c++) data[4 * i + c] = coordinates[dims * i + c];
      if (texels) data[4 * i + 3] = texels[i];
    }
    this.siteTexture.needsUpdate = true;
  }

  /** The float32 site coordinate the GPU sees (component c of site i). */
  siteCoordinate(i: number, c: number): number {
    return this.siteData[4 * i + c];
  }

  /**
   * Labels every texel with its nearest site. Cold: from scratch. Warm: from the previous
   * labels, given the largest distance (texels, an upper bound) any site moved since.
   */
  floodLabels(warmFromDisplacement?: number): void {
    const steps = this.schedules.steps(warmFromDisplacement, this.layout.floodHops?.(this.siteData, this.siteCount));
    if (warmFromDisplacement === undefined) {
      // glClear: far cheaper than a pass on software GL.
      this.renderer.setRenderTarget(this.labelTargets[this.current]);
      this.context.gl.clearBufferfv(this.context.gl.COLOR, 0, EMPTY_LABEL);
    } else {
      // Old coordinates -> the same ids' new coordinates.
      this.current = this.drawFrom(this.refreshPass, this.current);
    }
    // Splatting on top of old labels makes sure every site owns at least its own texel.
    this.splatPass.draw(this.renderer, this.labelTargets[this.current], this.siteCount);
    for (const step of steps) {
      this.floodPass.uniforms.stepSize.value = step;
      this.current = this.drawFrom(this.floodPass, this.current);
    }
    this.lastPassCount = steps.length;
  }

  /** Draws a pass reading the labels in target `from` into the other target; returns its index. */
  private drawFrom(pass: ShaderPass, from: number): number {
    pass.uniforms.labels.value = this.labelTargets[from].texture;
    pass.draw(this.renderer, this.labelTargets[1 - from]);
    return 1 - from;
  }

  /** Per-site sums over the current labels (see SUMS_STRIDE); result in `this.sums`. */
  computeSums(): Float64Array {
    const labels = this.labelTargets[this.current].texture;
    const { sums, siteCount, staging } = this;
    if (this.centroidPath === 'readback') {
      sums.fill(0);
      this.packedLabels.read(labels, this.accumulateBand);
      return sums;
    }
    if (this.gather) this.gather.compute(labels, staging, this.siteData, this.geometryData);
    else this.scatter(labels, false);
    // One pass gives (w dx, w dy, w, energy) on a grid, (w dx, w dy, w dz, w) on a cube map.
    const split = this.layout.defines.SPLIT_ENERGY === 1;
    for (let i = 0; i < siteCount; i++) {
      const o = SUMS_STRIDE * i;
      sums[o] = staging[4 * i];
      sums[o + 1] = staging[4 * i + 1];
      sums[o + 2] = split ? staging[4 * i + 2] : 0;
      sums[o + 3] = staging[4 * i + (split ? 3 : 2)];
      sums[o + 4] = split ? 0 : staging[4 * i + 3];
    }
    if (split) {
      this.scatter(labels, true);
      for (let i = 0; i < siteCount; i++) sums[SUMS_STRIDE * i + 4] = staging[4 * i];
    }
    return sums;
  }

  /** The readback path's reduction of one band of packed ids (a field: no closure per call). */
  private readonly accumulateBand = (ids: Int32Array, firstRow: number, rows: number): void =>
    this.layout.accumulate(ids, firstRow, rows, this.siteData, this.uniformWeights ? null : this.geometryData, this.siteCount, this.sums);

  /** The blend path: one additive scatter of every texel into the sums target, read into `staging`. */
  private scatter(labels: THREE.Texture, energyPass: boolean): void {
    const pass = this.scatterPass!;
    pass.uniforms.labels.value = labels;
    pass.uniforms.energyPass.value = energyPass;
    this.renderer.setRenderTarget(this.sumsTarget);
    this.renderer.setClearColor(0x000000, 0);
    this.renderer.clear(true, false, false);
    pass.draw(this.renderer, this.sumsTarget, this.layout.width * this.layout.height);
    readTargetRGBA(this.renderer, this.sumsTarget, this.staging);
  }

  /** Waits for the GPU (a one-texel readback); used to time passes apart. */
  sync(): void {
    readTargetRGBA(this.renderer, this.labelTargets[this.current], this.staging, 0, 0, 1, 1);
  }

  /** Reads the current labels: one site id (or -1) per texel, row-major over the atlas. */
  readLabels(out = new Int32Array(this.layout.width * this.layout.height)): Int32Array {
    const { width } = this.layout;
    this.packedLabels.read(this.labelTargets[this.current].texture, (ids, firstRow, rows) => out.set(ids.subarray(0, rows * width), firstRow * width));
    return out;
  }

  /** The gather path's windows and draws (null on the other paths). */
  get gatherStats(): GatherCentroids | null {
    return this.gather;
  }

  dispose(): void {
    for (const pass of [this.refreshPass, this.splatPass, this.floodPass, this.scatterPass]) pass?.dispose();
    for (const target of [...this.labelTargets, this.sumsTarget]) target.dispose();
    this.gather?.dispose();
    this.packedLabels.dispose();
    this.siteTexture.dispose();
    this.geometryTexture.dispose();
  }
}
