import * as THREE from 'three';

/** A float render target sampled with texelFetch only (nearest, no mipmaps, no depth). */
export function createFloatTarget(
  width: number,
  height: number,
  format: typeof THREE.RedFormat | typeof THREE.RGFormat | typeof THREE.RGBAFormat,
): THREE.WebGLRenderTarget {
  const target = new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format,
    depthBuffer: false,
    stencilBuffer: false,
    generateMipmaps: false,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    wrapS: THREE.ClampToEdgeWrapping,
    wrapT: THREE.ClampToEdgeWrapping,
  });
  target.texture.colorSpace = THREE.NoColorSpace;
  return target;
}

/** A float data texture we fill on the CPU and upload (sites, weights). */
export function createFloatDataTexture(
  data: Float32Array,
  width: number,
  height: number,
  format: typeof THREE.RedFormat | typeof THREE.RGBAFormat,
): THREE.DataTexture {
  const texture = new THREE.DataTexture(data, width, height, format, THREE.FloatType);
  texture.minFilter = THREE.NearestFilter;
  texture.magFilter = THREE.NearestFilter;
  texture.generateMipmaps = false;
  texture.flipY = false;
  texture.unpackAlignment = 1;
  texture.colorSpace = THREE.NoColorSpace;
  texture.needsUpdate = true;
  return texture;
}

/**
 * Reads a float target back into `out` (4 floats per texel, RGBA). WebGL2 always accepts
 * RGBA/FLOAT for float colour buffers, whatever their channel count.
 */
export function readTargetRGBA(
  renderer: THREE.WebGLRenderer,
  target: THREE.WebGLRenderTarget,
  out: Float32Array,
  x = 0,
  y = 0,
  width = target.width,
  height = target.height,
): Float32Array {
  if (out.length < width * height * 4) throw new RangeError('readback buffer too small');
  const gl = renderer.getContext() as WebGL2RenderingContext;
  renderer.setRenderTarget(target);
  gl.readPixels(x, y, width, height, gl.RGBA, gl.FLOAT, out);
  renderer.setRenderTarget(null);
  return out;
}
