/**
 * Draws a measured volume in a worker, on the OffscreenCanvas the page hands over
 * (volumeRenderer.ts): creating the WebGL context, compiling the programs, uploading the
 * surfaces (the tissue's and the model's), drawing and picking (a ray against every triangle) never run on the page's main
 * thread, which only forwards the pointer and shows the text (docs/app.md, "Measure a volume").
 */
import type { FromVolumeRenderer, ToVolumeRenderer } from './volumeRenderProtocol';
import { VolumeRenderer } from './volumeRenderer';

interface RenderWorkerScope {
  postMessage(message: FromVolumeRenderer): void;
  requestAnimationFrame?: (callback: () => void) => number;
}
const scope = self as unknown as RenderWorkerScope;
let renderer: VolumeRenderer | null = null;
let canvas: OffscreenCanvas | null = null;
let scheduled = false;
let frame = 0;

function draw(): void {
  if (scheduled) return;
  scheduled = true;
  const run = () => {
    scheduled = false;
    if (!renderer) return;
    renderer.render();
    scope.postMessage({ type: 'drawn', frame: ++frame });
  };
  if (scope.requestAnimationFrame) scope.requestAnimationFrame(run);
  else setTimeout(run, 16);
}

self.onmessage = (event: MessageEvent<ToVolumeRenderer>) => {
  const data = event.data;
  try {
    if (data.type === 'init') {
      canvas = data.canvas;
      renderer = new VolumeRenderer(data.canvas);
      renderer.setSize(data.width, data.height);
      return;
    }
    if (!renderer) throw new Error('the 3D view is not ready');
    if (data.type === 'size') renderer.setSize(data.width, data.height);
    else if (data.type === 'show') scope.postMessage({ type: 'shown', orbit: renderer.show(data.cells, data.surfaces, data.stripe) });
    else if (data.type === 'model') scope.postMessage({ type: 'modelShown', cells: renderer.showModel(data.cells, data.surfaces, data.stripe) });
    else if (data.type === 'layout') renderer.setLayout(data.layout);
    else if (data.type === 'orbit') renderer.setOrbit(data.orbit);
    else if (data.type === 'select') renderer.setSelected(data.row, data.cell);
    else if (data.type === 'shape') renderer.setShape(data.shape);
    else if (data.type === 'pick') {
      scope.postMessage({ type: 'picked', request: data.request, hit: renderer.pick(data.x, data.y) });
      return;
    } else if (data.type === 'png') {
      renderer.render();
      const request = data.request;
      void canvas!.convertToBlob({ type: 'image/png' }).then(
        (png) => scope.postMessage({ type: 'png', request, png }),
        (error: unknown) => scope.postMessage({ type: 'error', message: `the 3D view could not be saved: ${String(error)}` }),
      );
      return;
    }
    draw();
  } catch (error) {
    scope.postMessage({ type: 'error', message: error instanceof Error ? error.message : String(error) });
  }
};
