import { readFileSync } from 'node:fs';
import { GpuCapabilityError, wrapContext, type GpuContext } from '../gpu/context';
import { loadHeadlessGL } from './loadGL';

/**
 * A WebGL2 context in Node from headless-gl (`gl` 9.x). It needs an X display: run under
 * `xvfb-run -a` (the CLI re-executes itself that way when DISPLAY is unset). `gl` is an optional
 * dependency, loaded here and not at import time, so that the library imports without it and a
 * missing or unbuilt `gl` is one GpuCapabilityError saying what to install.
 */
export function createHeadlessContext(): GpuContext {
  const createGL = loadHeadlessGL();
  let created: WebGL2RenderingContext | null;
  try {
    created = createGL(1, 1, { createWebGL2Context: true });
  } catch (error) {
    throw headlessError(String(error));
  }
  if (!created) throw headlessError('createGL returned null');
  const context = created;
  const canvas = canvasStandIn(context);
  // three.js reads gl.canvas (e.g. in resetState), which headless-gl leaves undefined.
  if (!context.canvas) Object.defineProperty(context, 'canvas', { value: canvas });
  const destroy = () => (context.getExtension('STACKGL_destroy_context') as { destroy(): void } | null)?.destroy();
  return wrapContext(context, canvas, destroy, headlessRendererName());
}

/** The members of a canvas three.js uses when it is handed a context; Node has no canvas. */
type CanvasStandIn = Pick<HTMLCanvasElement, 'width' | 'height' | 'addEventListener' | 'removeEventListener'> & {
  style: object;
  getContext(contextId: string): WebGL2RenderingContext | null;
};

function canvasStandIn(context: WebGL2RenderingContext): HTMLCanvasElement {
  const standIn: CanvasStandIn = {
    width: 1,
    height: 1,
    style: {},
    addEventListener() {},
    removeEventListener() {},
    getContext: () => context,
  };
  return standIn as HTMLCanvasElement;
}

/**
 * headless-gl names its renderer "ANGLE" and nothing more; ANGLE draws through the system's
 * OpenGL driver, whose library is mapped into this process once a context exists. Its name
 * tells a CPU rasterizer (Mesa's swrast_dri.so: llvmpipe, the driver under Xvfb) from a GPU
 * driver (iris_dri.so, radeonsi_dri.so, NVIDIA's libGLX_nvidia), which decides the centroid
 * path "auto" takes. Linux only (/proc); elsewhere the name stays "ANGLE (headless-gl)".
 */
export function headlessRendererName(): string {
  let maps = '';
  try {
    maps = readFileSync('/proc/self/maps', 'utf8');
  } catch {
    return 'ANGLE (headless-gl)';
  }
  const dri = /\/dri\/(\w+)_dri\.so/.exec(maps);
  if (dri) return `ANGLE (headless-gl) on Mesa ${dri[1]}_dri${dri[1] === 'swrast' ? ' (software rasterizer)' : ''}`;
  if (/libGLX_nvidia/.test(maps)) return 'ANGLE (headless-gl) on NVIDIA';
  return 'ANGLE (headless-gl)';
}

function headlessError(detail: string): GpuCapabilityError {
  return new GpuCapabilityError(
    `Could not create a headless WebGL2 context (${detail}). headless-gl needs an X display: ` +
      'run the command under `xvfb-run -a` (apt-get install xvfb xauth libgl1-mesa-dri).',
  );
}
