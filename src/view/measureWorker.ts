/**
 * The page's measuring worker: decodes the label images, measures the tissue (measureTissue),
 * paints each layer's picture, then compares it with the Voronoi model (compareMeasured, the
 * CLI's --compare), so the page's main thread never decodes or counts (docs/app.md).
 */
import { compareMeasured, MeasureInputError, measureTissue, type LabelFileInput } from '../core/measure';
import { version } from '../version';
import { cellsByLabel, paintLayer, reduceLabels, type LayerLabels, type LayerPicture } from './measurePicture';
import type { FromMeasureWorker, ToMeasureWorker } from './measureProtocol';

/** What this worker uses of its global scope (the DOM typings describe a window). */
interface MeasureWorkerScope {
  postMessage(message: FromMeasureWorker, options?: StructuredSerializeOptions): void;
}
const scope = self as MeasureWorkerScope;
const post = (message: FromMeasureWorker, transfer: Transferable[] = []) => scope.postMessage(message, { transfer });

self.onmessage = (event: MessageEvent<ToMeasureWorker>) => {
  const { id, files, options } = event.data;
  try {
    const inputs: LabelFileInput[] = files.map((f) => ({ name: f.name, read: () => new Uint8Array(f.bytes) }));
    const reduced: LayerLabels[] = [];
    const result = measureTissue(inputs, {
      pixelSize: options.pixelSize,
      periodicX: options.periodicX,
      minContact: options.minContact,
      version,
      onProgress: (line) => post({ type: 'progress', id, line }),
      onLayerPixels: (_k, pixels) => reduced.push(reduceLabels(pixels, options.maxPictureSide)),
    });
    const cells = cellsByLabel(result.cells, reduced.length);
    const pictures: LayerPicture[] = reduced.map((layer, k) => ({
      ...layer,
      name: result.inputs.layers[k].name,
      rgba: paintLayer(layer, k, cells, options.periodicX),
    }));
    post(
      { type: 'measured', id, result, pictures },
      pictures.flatMap((p) => [p.rgba.buffer, p.labels.buffer]),
    );
    if (options.realizations > 0) {
      const { comparison, note } = compareMeasured(result, {
        realizations: options.realizations,
        seed: options.seed,
        onProgress: (line) => post({ type: 'progress', id, line }),
      });
      post({ type: 'compared', id, comparison, note });
    }
  } catch (error) {
    const file = error instanceof MeasureInputError ? error.file : null;
    post({ type: 'error', id, file, message: error instanceof Error ? error.message : String(error) });
  }
};
