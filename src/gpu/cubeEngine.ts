import * as THREE from 'three';
import { texelEdgeTable } from '../core/cubemap/cubemap';
import { FloodSchedules, type JumpFloodVariant } from '../core/jumpSchedule';
import centroidScatterFrag from '../shaders/centroidScatter.frag';
import clearLabelsFrag from '../shaders/clearLabels.frag';
import cubeCentroidScatterVert from '../shaders/cubeCentroidScatter.vert';
import cubeJumpFloodFrag from '../shaders/cubeJumpFlood.frag';
import cubeSplatVert from '../shaders/cubeSplat.vert';
import fullscreenVert from '../shaders/fullscreen.vert';
import splatFrag from '../shaders/splat.frag';
import { chooseCentroidPath, type RequestedCentroidPath } from './centroidPolicy';
import { GpuCapabilityError, type GpuContext } from './context';
import { PackedLabels } from './packedLabels';
import { floodPingPong } from './pingPong';
import { ShaderPass } from './shaderPass';
import { createFloatDataTexture, createFloatTarget, readTargetRGBA } from './textures';

/**
 * How a closed surface's centroid sums are made: additive blending on the GPU (needs
 * EXT_float_blend), or the portable path: the label texture is read back and reduced on the
 * CPU in float64 (6 n² texels, a few ms at n = 128; no allocation per iteration).
 */
export type CubeCentroidPath = 'blend' | 'readback';

export interface CubeEngineOptions {
  readonly variant: JumpFloodVariant;
  /** 'auto' and the other choices: see chooseCentroidPath ('gather' means readback here). */
  readonly centroidPath: RequestedCentroidPath;
}

/** Values per site in `CubeCcvtEngine.sums`: w·dx, w·dy, w·dz, w, w·|d|² (d = texel point - site). */
export const CUBE_SUMS_STRIDE = 5;

/**
 * The GPU half of Lloyd's method on a cube-map geometry image (a closed surface): splat, jump
 * flood across face edges with 3D distances, centroid sums. The geometry (per-texel 3D point
 * and weight) is a texture that can be replaced (setGeometry), so one engine labels every
 * surface of a sheet's stack. Everything is created in the constructor; the loop allocates
 * nothing and compiles nothing.
 */
export class CubeCcvtEngine {
  readonly centroidPath: CubeCentroidPath;
  readonly width: number;
  readonly height: number;
  readonly siteTextureWidth: number;
  readonly siteTextureHeight: number;
  /** Per site after computeSums(): CUBE_SUMS_STRIDE values (float64). */
  readonly sums: Float64Array;
  lastPassCount = 0;

  private readonly renderer: THREE.WebGLRenderer;
  private readonly siteData: Float32Array;
  private readonly siteTexture: THREE.DataTexture;
  private readonly geometryData: Float32Array;
  private readonly geometryTexture: THREE.DataTexture;
  private readonly labelTargets: [THREE.WebGLRenderTarget, THREE.WebGLRenderTarget];
  private current = 0;
  private readonly sumsTargets: THREE.WebGLRenderTarget[] = [];
  private readonly sumsStaging: Float32Array;
  private readonly packedLabels: PackedLabels;
  private readonly labelBuffer: Int32Array;
  private readonly clearPass: ShaderPass;
  private readonly splatPass: ShaderPass;
  private readonly floodPass: ShaderPass;
  private readonly scatterPass: ShaderPass | null = null;
  private readonly schedules: FloodSchedules;

  constructor(
    private readonly context: GpuContext,
    readonly n: number,
    readonly siteCount: number,
    options: CubeEngineOptions,
  ) {
    const { maxTextureSize } = context.capabilities;
    this.width = n;
    this.height = 6 * n;
    if (this.height > maxTextureSize) {
      throw new GpuCapabilityError(
        `resolution: the cube map is ${n} x ${6 * n} texels (6 faces of ${n}²) but this GPU allows at most ${maxTextureSize} per side; lower resolution to at most ${Math.floor(maxTextureSize / 6)}`,
      );
    }
    this.centroidPath = chooseCentroidPath('cube map', options.centroidPath, context.capabilities).path as CubeCentroidPath;
    this.renderer = context.renderer;

    this.siteTextureWidth = Math.min(siteCount, maxTextureSize);
    this.siteTextureHeight = Math.ceil(siteCount / this.siteTextureWidth);
    this.siteData = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.siteTexture = createFloatDataTexture(this.siteData, this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat);
    this.geometryData = new Float32Array(this.width * this.height * 4);
    this.geometryTexture = createFloatDataTexture(this.geometryData, this.width, this.height, THREE.RGBAFormat);
    this.labelTargets = [createFloatTarget(this.width, this.height, THREE.RedFormat), createFloatTarget(this.width, this.height, THREE.RedFormat)];
    this.sums = new Float64Array(siteCount * CUBE_SUMS_STRIDE);
    this.sumsStaging = new Float32Array(this.siteTextureWidth * this.siteTextureHeight * 4);
    this.labelBuffer = new Int32Array(this.width * this.height);
    this.schedules = new FloodSchedules(n, n, options.variant);

    const metric = {
      faceSize: { value: n },
      edgeTable: { value: Array.from(texelEdgeTable(n)) },
      positions: { value: this.geometryTexture },
      sites: { value: this.siteTexture },
      siteWidth: { value: this.siteTextureWidth },
    };
    this.clearPass = new ShaderPass('triangles', fullscreenVert, clearLabelsFrag, {});
    // The planar engine's packed-id readback; here the labels are the ids themselves.
    this.packedLabels = new PackedLabels(
      this.renderer,
      { width: this.width, height: this.height },
      { labels: { value: this.labelTargets[0].texture as THREE.Texture } },
      { LABELS_ARE_IDS: 1, PERIODIC_X: 0, PERIODIC_Y: 0 },
    );
    this.splatPass = new ShaderPass('points', cubeSplatVert, splatFrag, { ...metric });
    this.floodPass = new ShaderPass('triangles', fullscreenVert, cubeJumpFloodFrag, {
      ...metric,
      labels: { value: this.labelTargets[0].texture as THREE.Texture },
      stepSize: { value: 1 },
    });
    if (this.centroidPath === 'blend') {
      this.sumsTargets = [0, 1].map(() => createFloatTarget(this.siteTextureWidth, this.siteTextureHeight, THREE.RGBAFormat));
      this.scatterPass = new ShaderPass(
        'points',
        cubeCentroidScatterVert,
        centroidScatterFrag,
        {
          ...metric,
          labels: { value: this.labelTargets[0].texture as THREE.Texture },
          sumsSize: { value: new THREE.Vector2(this.siteTextureWidth, this.siteTextureHeight) },
          energyPass: { value: false },
        },
        true,
      );
    }
  }

  /**
   * Uploads the surface the next floods run on: xyz per texel (6 n² x 3, atlas order) and the
   * weight per texel (density x area element, µm²).
   */
  setGeometry(position: ArrayLike<number>, weight: ArrayLike<number>): void {
    const count = this.width * this.height;
    if (position.length !== 3 * count || weight.length !== count) throw new RangeError('setGeometry: wrong size');
    const data = this.geometryData;
    for (let k = 0; k < count; k++) {
      data[4 * k] = position[3 * k];
      data[4 * k + 1] = position[3 * k + 1];
      data[4 * k + 2] = position[3 * k + 2];
      data[4 * k + 3] = weight[k];
    }
    this.geometryTexture.needsUpdate = true;
  }

  /** Uploads sites: xyz per site (µm) and the atlas index of the texel each lies in. */
  setSites(positions: ArrayLike<number>, texels: ArrayLike<number>): void {
    const data = this.siteData;
    for (let i = 0; i < this.siteCount; i++) {
      data[4 * i] = positions[3 * i];
      data[4 * i + 1] = positions[3 * i + 1];
      data[4 * i + 2] = positions[3 * i + 2];
      data[4 * i + 3] = texels[i];
    }
    this.siteTexture.needsUpdate = true;
  }

  /** The float32 site coordinate the GPU sees (component c of site i). */
  siteCoordinate(i: number, c: number): number {
    return this.siteData[4 * i + c];
  }

  /**
   * Labels every texel with its nearest site (3D distance). Cold: from scratch. Warm: from
   * the previous labels, given how far (in texels, an upper bound) any site moved since.
   */
  floodLabels(warmFromTexels?: number): void {
    const steps = this.schedules.steps(warmFromTexels);
    if (warmFromTexels === undefined) this.clearPass.draw(this.renderer, this.labelTargets[this.current]);
    this.splatPass.draw(this.renderer, this.labelTargets[this.current], this.siteCount);
    this.current = floodPingPong(this.renderer, this.floodPass, this.labelTargets, this.current, steps);
    this.lastPassCount = steps.length;
  }

  /** Per-site sums over the current labels (see CUBE_SUMS_STRIDE); result in `this.sums`. */
  computeSums(): Float64Array {
    const sums = this.sums;
    if (this.centroidPath === 'blend' && this.scatterPass) {
      const pass = this.scatterPass;
      pass.uniforms.labels.value = this.labelTargets[this.current].texture;
      for (let k = 0; k < 2; k++) {
        const target = this.sumsTargets[k];
        this.renderer.setRenderTarget(target);
        this.renderer.setClearColor(0x000000, 0);
        this.renderer.clear(true, false, false);
        pass.uniforms.energyPass.value = k === 1;
        pass.draw(this.renderer, target, this.width * this.height);
        readTargetRGBA(this.renderer, target, this.sumsStaging);
        for (let i = 0; i < this.siteCount; i++) {
          if (k === 0) for (let c = 0; c < 4; c++) sums[CUBE_SUMS_STRIDE * i + c] = this.sumsStaging[4 * i + c];
          else sums[CUBE_SUMS_STRIDE * i + 4] = this.sumsStaging[4 * i];
        }
      }
      return sums;
    }
    // Portable path: read the labels back, reduce in float64 against the float32 values the
    // GPU flooded with.
    const labels = this.readLabels(this.labelBuffer);
    sums.fill(0);
    const g = this.geometryData;
    const s = this.siteData;
    for (let k = 0; k < labels.length; k++) {
      const id = labels[k];
      if (id < 0) continue;
      const w = g[4 * k + 3];
      const dx = g[4 * k] - s[4 * id];
      const dy = g[4 * k + 1] - s[4 * id + 1];
      const dz = g[4 * k + 2] - s[4 * id + 2];
      const o = CUBE_SUMS_STRIDE * id;
      sums[o] += w * dx;
      sums[o + 1] += w * dy;
      sums[o + 2] += w * dz;
      sums[o + 3] += w;
      sums[o + 4] += w * (dx * dx + dy * dy + dz * dz);
    }
    return sums;
  }

  /** Reads the current labels: one site id (or -1) per texel, atlas order (index (f n + j) n + i). */
  readLabels(out: Int32Array = new Int32Array(this.width * this.height)): Int32Array {
    const { width } = this;
    this.packedLabels.read(this.labelTargets[this.current].texture, (ids, firstRow, rows) => {
      out.set(ids.subarray(0, rows * width), firstRow * width);
    });
    return out;
  }

  /** Waits for the GPU (a one-texel readback). */
  sync(): void {
    readTargetRGBA(this.renderer, this.labelTargets[this.current], this.sumsStaging, 0, 0, 1, 1);
  }

  dispose(): void {
    for (const pass of [this.clearPass, this.splatPass, this.floodPass, this.scatterPass]) pass?.dispose();
    for (const target of [...this.labelTargets, ...this.sumsTargets]) target.dispose();
    this.packedLabels.dispose();
    this.siteTexture.dispose();
    this.geometryTexture.dispose();
  }
}
