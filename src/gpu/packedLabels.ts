import * as THREE from 'three';
import type { ShaderPass } from './shaderPass';

/** Texels per readback band: bounds the staging buffer (4 MiB) on the largest grids. */
const BAND_TEXELS = 1 << 20;

/** The id view below reads the packed bytes as little-endian; say so rather than misread. */
const LITTLE_ENDIAN = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

/**
 * Site ids of a flood read back to the CPU, 4 bytes a texel: a pass packs each texel's id into
 * an RGBA8 target (shaders/packIds.frag), which is read in bands of rows into one staging
 * buffer viewed as an Int32Array (-1 for an empty texel). A float readback would move four
 * times the bytes. Everything is created here, so a readback allocates nothing.
 */
export class PackedLabels {
  private readonly target: THREE.WebGLRenderTarget;
  private readonly bytes: Uint8Array;
  private readonly ids: Int32Array;
  private readonly rowsPerBand: number;

  constructor(
    private readonly renderer: THREE.WebGLRenderer,
    private readonly grid: { readonly width: number; readonly height: number },
    /** The packing pass (shaders/packIds.frag, with a `labels` uniform). */
    private readonly pass: ShaderPass,
  ) {
    if (!LITTLE_ENDIAN) throw new Error('tissue-sheet reads packed label ids as little-endian; this platform is big-endian');
    this.target = new THREE.WebGLRenderTarget(grid.width, grid.height, {
      type: THREE.UnsignedByteType,
      format: THREE.RGBAFormat,
      depthBuffer: false,
      stencilBuffer: false,
      generateMipmaps: false,
      minFilter: THREE.NearestFilter,
      magFilter: THREE.NearestFilter,
    });
    this.target.texture.colorSpace = THREE.NoColorSpace;
    this.rowsPerBand = Math.max(1, Math.min(grid.height, Math.floor(BAND_TEXELS / grid.width)));
    this.ids = new Int32Array(this.rowsPerBand * grid.width);
    this.bytes = new Uint8Array(this.ids.buffer);
  }

  /**
   * Packs the ids of `labels` and hands them over band by band: `visit(ids, firstRow, rows)`, with `ids` holding
   * rows firstRow .. firstRow + rows - 1, row-major. `ids` is reused by the next band.
   */
  read(labels: THREE.Texture, visit: (ids: Int32Array, firstRow: number, rows: number) => void): void {
    this.pass.uniforms.labels.value = labels;
    this.pass.draw(this.renderer, this.target);
    const gl = this.renderer.getContext() as WebGL2RenderingContext;
    const { width, height } = this.grid;
    this.renderer.setRenderTarget(this.target);
    for (let y0 = 0; y0 < height; y0 += this.rowsPerBand) {
      const rows = Math.min(this.rowsPerBand, height - y0);
      gl.readPixels(0, y0, width, rows, gl.RGBA, gl.UNSIGNED_BYTE, this.bytes);
      visit(this.ids, y0, rows);
    }
    this.renderer.setRenderTarget(null);
  }

  dispose(): void {
    this.pass.dispose();
    this.target.dispose();
  }
}
