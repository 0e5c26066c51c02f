import * as THREE from 'three';

/** What the engine needs to know about the WebGL2 context it runs on. */
export interface GpuCapabilities {
  /** Renderer string (e.g. "ANGLE (Google, Vulkan 1.3.0 (SwiftShader ...))"). */
  readonly renderer: string;
  readonly maxTextureSize: number;
  /** Additive blending into RGBA32F targets (the fast centroid path). */
  readonly floatBlend: boolean;
  /** The renderer rasterizes on the CPU (SwiftShader, llvmpipe, ...), not on a GPU. */
  readonly softwareRenderer: boolean;
}

/** Renderer strings of CPU rasterizers (Chromium's SwiftShader, Mesa's llvmpipe/softpipe, WARP). */
const SOFTWARE_RENDERER = /swiftshader|llvmpipe|softpipe|swrast|software rasterizer|basic render driver/i;

/** A three.js renderer bound to a WebGL2 context, in a page or in Node (headless-gl). */
export interface GpuContext {
  readonly renderer: THREE.WebGLRenderer;
  readonly gl: WebGL2RenderingContext;
  readonly capabilities: GpuCapabilities;
  dispose(): void;
}

/** A missing GPU capability; the message says what is missing and what to do. */
export class GpuCapabilityError extends Error {
  override readonly name = 'GpuCapabilityError';
}

/**
 * Wraps an existing WebGL2 context (from a canvas or from headless-gl) in a three.js renderer
 * and checks the extensions the engine needs. `canvas` may be a minimal stand-in in Node.
 */
export function wrapContext(
  gl: WebGL2RenderingContext,
  canvas: HTMLCanvasElement | OffscreenCanvas,
  onDispose: () => void = () => {},
  /** The renderer's name where the context cannot tell it (headless-gl says only "ANGLE"). */
  rendererName?: string,
): GpuContext {
  if (typeof WebGL2RenderingContext !== 'undefined' && !(gl instanceof WebGL2RenderingContext)) {
    // headless-gl has its own class; only a browser's WebGL1 context lands here.
    if (!('texStorage2D' in gl)) throw noWebGL2();
  }
  if (!gl.getExtension('EXT_color_buffer_float')) {
    throw new GpuCapabilityError(
      'This WebGL2 context cannot render to float textures (EXT_color_buffer_float is missing); ' +
        'tissue-sheet needs it for labels and centroids. Try a current desktop browser.',
    );
  }
  const floatBlend = gl.getExtension('EXT_float_blend') !== null;
  const renderer = new THREE.WebGLRenderer({ canvas: canvas as HTMLCanvasElement, context: gl });
  renderer.autoClear = false;
  const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
  const name = rendererName ?? String(gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER) ?? 'unknown');
  return {
    renderer,
    gl,
    capabilities: {
      renderer: name,
      maxTextureSize: gl.getParameter(gl.MAX_TEXTURE_SIZE) as number,
      floatBlend,
      softwareRenderer: SOFTWARE_RENDERER.test(name),
    },
    dispose() {
      renderer.dispose();
      onDispose();
    },
  };
}

function noWebGL2(): GpuCapabilityError {
  return new GpuCapabilityError(
    'WebGL2 is not available here, and tissue-sheet computes on the GPU with WebGL2. ' +
      'Enable hardware acceleration or WebGL in the browser settings, or use a current browser.',
  );
}

/** Creates a context on a canvas in a page. */
export function createCanvasContext(canvas: HTMLCanvasElement | OffscreenCanvas): GpuContext {
  const gl = canvas.getContext('webgl2', {
    antialias: false,
    depth: false,
    stencil: false,
    preserveDrawingBuffer: false,
    powerPreference: 'high-performance',
  }) as WebGL2RenderingContext | null;
  if (!gl) throw noWebGL2();
  return wrapContext(gl, canvas);
}
