/**
 * The page's volume-measuring worker (docs/app.md, "Measure a volume"): the CLI's own core
 * (measureVolume, then compareVolume: the model of the same geometry, a closed shell on its own
 * meshes, an open piece as the fitted tube), and the surfaces to draw (volumeSurfaces.ts; the
 * model's first realization, volumeModelDrawing, also for a saved comparison), so the
 * page's main thread never decodes, classifies or meshes. The classified voxels of the last
 * volume stay here to build a picked cell's 3D shape on request.
 */
import {
  compareVolume,
  MeasureInputError,
  measureVolume,
  volumeModelDrawing,
  type ClassifiedVolume,
  type ShellMeshes,
  type VolumeModelDrawing,
} from '../core/measure';
import { version } from '../version';
import { PAGE_MAX_BYTES } from './pageBudget';
import type { FromVolumeWorker, ToVolumeWorker } from './volumeProtocol';
import { cellShape, drawSurface } from './volumeSurfaces';

/** What this worker uses of its global scope (the DOM typings describe a window). */
interface VolumeWorkerScope {
  postMessage(message: FromVolumeWorker, options?: StructuredSerializeOptions): void;
}
const scope = self as VolumeWorkerScope;
const post = (message: FromVolumeWorker, transfer: Transferable[] = []) => scope.postMessage(message, { transfer });

let kept: ClassifiedVolume | null = null;

const drawingBuffers = (d: VolumeModelDrawing): ArrayBuffer[] => [
  d.valid.buffer as ArrayBuffer,
  d.scutoid.buffer as ArrayBuffer,
  ...d.surfaces.flatMap((s) => [s.positions, s.cells, s.sites, s.sides, s.offsets, s.neighbours].map((a) => a.buffer as ArrayBuffer)),
];

self.onmessage = (event: MessageEvent<ToVolumeWorker>) => {
  const data = event.data;
  const id = data.id;
  try {
    if (data.type === 'cell') {
      if (!kept) throw new Error('no measured volume to pick a cell from');
      const shape = cellShape(kept, data.cell);
      post({ type: 'cell', id, shape }, [shape.positions.buffer, shape.indices.buffer]);
      return;
    }
    const { file, options } = data;
    kept = null;
    let meshes: ShellMeshes | undefined;
    let voxels: ClassifiedVolume | null = null;
    const progress = (line: string) => post({ type: 'progress', id, line });
    const result = measureVolume(
      { name: file.name, read: () => new Uint8Array(file.bytes) },
      {
        voxelSize: options.voxelSize,
        apical: options.apical,
        minContact: options.minContact,
        lumenLabel: options.lumenLabel,
        quartetFilter: options.quartetFilter,
        memory: { maxBytes: PAGE_MAX_BYTES, why: "a page may take (the command-line tool allows half the machine's memory: tissue-sheet measure --volume)" },
        version,
        onProgress: progress,
        onSurfaceMeshes: options.realizations > 0 || options.saved ? (m) => (meshes = m) : undefined,
        onVoxels: (v) => (voxels = v),
      },
    );
    const classified = voxels as ClassifiedVolume | null;
    if (!classified) throw new Error('measureVolume gave no voxels');
    progress('drawing the basal and apical surfaces…');
    const surfaces = result.inputs.layers.map((layer) => drawSurface(classified, layer.name, layer.faces, layer.area));
    kept = classified;
    post(
      { type: 'measured', id, result, surfaces },
      surfaces.flatMap((s) => [s.positions.buffer, s.cells.buffer]),
    );
    let compared: ReturnType<typeof compareVolume>;
    if (options.realizations > 0) compared = compareVolume(result, { realizations: options.realizations, seed: options.seed, onProgress: progress }, meshes);
    else if (options.saved) compared = { comparison: options.saved, note: '' };
    else return;
    const { comparison, note } = compared;
    progress('drawing the model of the same geometry…');
    const { drawing, note: drawingNote } = comparison ? volumeModelDrawing(result, comparison, meshes) : { drawing: null, note: '' };
    post({ type: 'compared', id, comparison, note, drawing, drawingNote }, drawing ? drawingBuffers(drawing) : []);
  } catch (error) {
    const file = error instanceof MeasureInputError ? error.file : null;
    post({ type: 'error', id, file, message: error instanceof Error ? error.message : String(error) });
  }
};
