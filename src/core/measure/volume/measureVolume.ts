/**
 * Measures a 3D label volume of a curved epithelium (docs/measure.md, "Measuring a volume"):
 * decode, classify the background into outside / lumen, find each cell's faces on both
 * surfaces and the contact curves between cells there (lengths in µm along the curve), then
 * run the same analysis as the layers mode and a simulated stack on [basal, apical].
 */
import { adjacencyFromLists, analysisRecord, analyzeSurfaces, labMinBoundaryLength, type SurfaceAdjacency } from '../../analysis';
import { BORDER_EXCLUDED } from '../../border';
import { MeasureInputError } from '../errors';
import type { LabelFileInput } from '../layerPlan';
import type { MeasuredAnalysis } from '../measuredResult';
import { parseImageJDescription } from '../pixelSize';
import { contactCurves, type Curves } from './contactCurves';
import { scanContactEdges } from './contactEdges';
import { scanFaces, type FaceScan, type FaceTally } from './faceScan';
import { quartetFilter } from './quartets';
import { decodeVolumeTiff, inspectVolumeTiff, MAX_VOLUME_VOXELS, type VolumeHeader } from './tiffVolume';
import { chooseVoxelSize, parseOme, type VoxelSize } from './voxelSize';
import { classifyVoxels, LUMEN, OUTSIDE, type VoxelClasses } from './voxelClasses';
import { maskSurfaceMesh, type SurfaceMesh } from './surfaceMesh';
import { backgroundRecord, centroid, exclusionOf, LAYER_NAMES, lateralContacts } from './volumeRecords';
import type { VolumeCellRecord, VolumeContactRecord, VolumeMeasuredResult, VolumeSurfaceRecord } from './volumeResult';

export interface MeasureVolumeOptions {
  /** µm along width, height and between pages; overrides the file's metadata. */
  readonly voxelSize?: { x: number; y: number; z: number };
  /** Which background the apical surface faces (default the lumen). */
  readonly apical?: 'lumen' | 'outside';
  /** Voxels with this label are lumen, not a cell. */
  readonly lumenLabel?: number;
  /** Shortest contact curve (µm) that makes two cells neighbours; default per surface. */
  readonly minContact?: number;
  readonly quartetFilter?: boolean;
  /** Largest volume accepted (voxels); default MAX_VOLUME_VOXELS. */
  readonly maxVoxels?: number;
  /**
   * Memory the measurement may take (bytes, estimated from the header before anything is
   * decoded: a few megabytes of Deflate can declare gigabytes of voxels), and what to say where
   * it is over; default no bound beyond maxVoxels.
   */
  readonly memory?: { readonly maxBytes: number; readonly why: string };
  readonly version: string;
  readonly onProgress?: (line: string) => void;
  /**
   * Called with both surfaces as triangle meshes (surfaceMesh.ts; vertices about a fifth of the
   * lumen side's mean cell diameter apart), built while the classified voxels are at hand: what
   * the model of a closed shell runs on (compareVolume).
   */
  readonly onSurfaceMeshes?: (meshes: { lumen: SurfaceMesh; outer: SurfaceMesh; spacing: number }) => void;
  /**
   * Called once measured with the classified voxels (dense ids and classes): what the page's
   * worker keeps to draw the surfaces and a picked cell's shape (src/view/volumeSurfaces.ts).
   */
  readonly onVoxels?: (voxels: ClassifiedVolume) => void;
}

/** The classified voxels of a measured volume, with its dimensions and voxel size (µm). */
export interface ClassifiedVolume {
  readonly classes: VoxelClasses;
  readonly width: number;
  readonly height: number;
  readonly depth: number;
  readonly voxelSize: { readonly x: number; readonly y: number; readonly z: number };
}

const now = () => performance.now();

/**
 * Bytes a voxel takes while it is measured beside its label: its class (1) and its share of the
 * background components' union-find (about 1). Measured: 8192 x 8192 x 4 voxels of 32 bits
 * peaked at 1.64 GB, 16384 x 16384 x 4 at 6.36 GB (4 + 2 bytes a voxel).
 */
const WORKING_BYTES_PER_VOXEL = 2;

/** Refuses a volume whose decoded voxels and working arrays would not fit `memory.maxBytes`. */
function checkVolumeMemory(header: VolumeHeader, fileBytes: number, name: string, memory: { maxBytes: number; why: string }): void {
  const voxels = header.width * header.height * header.depth;
  const bytes = fileBytes + voxels * (header.bitsPerSample / 8 + WORKING_BYTES_PER_VOXEL);
  if (bytes > memory.maxBytes) {
    const gib = (b: number) => (b >= 2 ** 30 ? `${(b / 2 ** 30).toFixed(1)} GiB` : `${Math.ceil(b / 2 ** 20)} MiB`);
    throw new MeasureInputError(
      name,
      `${header.width} x ${header.height} x ${header.depth} voxels of ${header.bitsPerSample} bits need about ${gib(bytes)} to measure, ` +
        `over the ${gib(memory.maxBytes)} ${memory.why}; crop the volume to the tissue or bin it (fewer voxels) first`,
    );
  }
}

export function measureVolume(file: LabelFileInput, options: MeasureVolumeOptions): VolumeMeasuredResult {
  const start = now();
  const name = file.name;
  let bytes: Uint8Array | null = file.read();
  const fileBytes = bytes.length;
  const header = inspectVolumeTiff(bytes, name, options.maxVoxels ?? MAX_VOLUME_VOXELS);
  checkHyperstack(header.chain.description, name, header.depth);
  if (options.memory) checkVolumeMemory(header, fileBytes, name, options.memory);
  const { voxelSize, warnings } = chooseVoxelSize(header.chain, name, options.voxelSize);
  const volume = decodeVolumeTiff(bytes, name, header);
  bytes = null; // the decoded volume is all we need from here
  const { width: W, height: H, depth: D } = volume;
  options.onProgress?.(
    `read ${name}: ${W} x ${H} x ${D} voxels, ${volume.bitsPerSample}-bit, voxel ${voxelSize.x} x ${voxelSize.y} x ${voxelSize.z} µm (${voxelSize.source})`,
  );
  const readMs = now() - start;

  const t1 = now();
  const classes = classifyVoxels(volume, name, options.lumenLabel);
  const lumenComponents = classes.components.filter((c) => c.kind === 'lumen');
  if (lumenComponents.length === 0 && classes.labelledLumenVoxels === 0) {
    throw new MeasureInputError(
      name,
      'no lumen: all background is one component connected to the outside; a volume needs a lumen (a cyst, organoid or tube), or give --lumen-label N; lines of 0 between cells join the lumen to the outside: remove them (e.g. by dilating the labels) first',
    );
  }
  const classifyMs = now() - t1;

  const t2 = now();
  const cells = classes.labels.length;
  const faces = scanFaces(classes.ids, classes.classes, W, H, D, cells, voxelSize);
  const edges = scanContactEdges(classes.ids, classes.classes, W, H, D);
  const apicalFacesOutside = options.apical === 'outside';
  // Layer 0 basal, layer 1 apical: which background class each faces.
  const layerClass = apicalFacesOutside ? [LUMEN, OUTSIDE] : [OUTSIDE, LUMEN];
  const curves = layerClass.map((s) => contactCurves(edges, s, W, H, voxelSize));
  const contactsMs = now() - t2;
  options.onProgress?.(`contacts: ${cells} cells, ${edges.count} contact edges, ${curves[0].size} basal and ${curves[1].size} apical contact curves`);

  const t3 = now();
  const result = assemble(
    name,
    fileBytes,
    header.chain.pages.length,
    volume.bitsPerSample,
    W,
    H,
    D,
    voxelSize,
    classes,
    faces,
    curves,
    layerClass,
    options,
    warnings,
  );
  const analysisMs = now() - t3;
  if (options.onSurfaceMeshes) {
    const lumenLayer = result.inputs.layers.find((l) => l.faces === 'lumen')!;
    const spacing = Math.sqrt(lumenLayer.area / Math.max(1, lumenLayer.cells)) / 5;
    const mesh = (inMask: (c: number) => boolean) => maskSurfaceMesh(classes.classes, W, H, D, voxelSize, inMask, spacing);
    options.onSurfaceMeshes({ lumen: mesh((c) => c === LUMEN), outer: mesh((c) => c !== OUTSIDE), spacing });
  }
  options.onVoxels?.({ classes, width: W, height: H, depth: D, voxelSize: { x: voxelSize.x, y: voxelSize.y, z: voxelSize.z } });
  return { ...result, timings: { readMs, classifyMs, contactsMs, analysisMs, totalMs: now() - start } };
}

/** ImageJ hyperstacks and OME files with several channels or time points are not one label volume. */
function checkHyperstack(description: string | null, file: string, pages: number): void {
  const imagej = parseImageJDescription(description ?? undefined);
  if (imagej && imagej.channels > 1) throw new MeasureInputError(file, `an ImageJ hyperstack with ${imagej.channels} channels; save the label channel alone`);
  if (imagej && imagej.frames > 1) throw new MeasureInputError(file, `an ImageJ hyperstack with ${imagej.frames} time points; save one time point`);
  const ome = parseOme(description);
  if (ome && ome.channels > 1) throw new MeasureInputError(file, `an OME-TIFF with ${ome.channels} channels; save the label channel alone`);
  if (ome && ome.times > 1) throw new MeasureInputError(file, `an OME-TIFF with ${ome.times} time points; save one time point`);
  if (ome && ome.slices !== null && ome.slices !== pages) {
    throw new MeasureInputError(
      file,
      `its OME-XML says SizeZ=${ome.slices} but it has ${pages} pages${ome.images > 1 ? ` (${ome.images} images)` : ''}; save one image of one channel`,
    );
  }
}

function assemble(
  file: string,
  fileBytes: number,
  pages: number,
  bitsPerSample: 8 | 16 | 32,
  W: number,
  H: number,
  D: number,
  voxelSize: VoxelSize,
  classes: VoxelClasses,
  faces: FaceScan,
  curves: Curves[],
  layerClass: number[],
  options: MeasureVolumeOptions,
  warnings: string[],
): Omit<VolumeMeasuredResult, 'timings'> {
  const n = classes.labels.length;
  const { x: sx, y: sy, z: sz } = voxelSize;
  const faceArea: [number, number, number] = [sy * sz, sx * sz, sx * sy];
  const tallies: FaceTally[] = layerClass.map((s) => (s === OUTSIDE ? faces.outside : faces.lumen));

  // Areas (µm²) per layer per cell (dense 0-based), and which cells reach each layer.
  const areas = tallies.map((t) => t.area.slice(1));
  const reaches = tallies.map((t) => Uint8Array.from({ length: n }, (_, i) => (t.counts[3 * i + 3] + t.counts[3 * i + 4] + t.counts[3 * i + 5] > 0 ? 1 : 0)));

  // Area and number of the cells that reach surface k.
  const reaching = [0, 1].map((k) => {
    let area = 0;
    let count = 0;
    for (let i = 0; i < n; i++) {
      if (!reaches[k][i]) continue;
      area += areas[k][i];
      count++;
    }
    return { area, count };
  });
  const minContacts = [0, 1].map((k) => {
    if (options.minContact !== undefined) return options.minContact;
    const { area, count } = reaching[k];
    return count > 0 ? labMinBoundaryLength(area, count) : 0;
  });

  // A cell that misses a surface or is cut by the volume's bounds is left out of the statistics.
  const invalid = new Uint8Array(n);
  for (let i = 0; i < n; i++) if (!reaches[0][i] || !reaches[1][i] || faces.volumeFaces[i + 1] !== 0) invalid[i] = BORDER_EXCLUDED;

  // Neighbour sets per layer (dense 0-based ids) after min-contact, then the optional quartet filter.
  const lengthOf = curves.map((c) => (a: number, b: number) => c.get(Math.min(a, b) * 2 ** 26 + Math.max(a, b))?.length ?? 0);
  let sets = curves.map((c, k) => {
    const s: Set<number>[] = Array.from({ length: n }, () => new Set<number>());
    for (const curve of c.values()) {
      if (curve.length < minContacts[k]) continue;
      s[curve.a - 1].add(curve.b - 1);
      s[curve.b - 1].add(curve.a - 1);
    }
    return s;
  }) as [Set<number>[], Set<number>[]];
  let quartetRecord: VolumeMeasuredResult['quartetFilter'] = null;
  if (options.quartetFilter) {
    const filtered = quartetFilter(sets);
    sets = filtered.sets;
    const label = (i: number) => classes.labels[i];
    quartetRecord = {
      quartets: filtered.quartets.map((q) => q.map(label)),
      removed: filtered.removed.map(([a, b, layer]) => ({ labels: [label(a), label(b)] as [number, number], layer })),
    };
  }

  const surfaces: SurfaceAdjacency[] = [0, 1].map((k) => {
    const lists = sets[k].map((s) => [...s].sort((x, y) => x - y));
    const lengths = lists.map((list, i) => list.map((j) => lengthOf[k](i + 1, j + 1)));
    return adjacencyFromLists(lists, lengths, areas[k], invalid, LAYER_NAMES[k]);
  });
  const analysis = analyzeSurfaces(surfaces);
  const record = analysisRecord('labels', minContacts[0], analysis);
  const measuredAnalysis: MeasuredAnalysis = {
    ...record,
    method: 'labels',
    cells: record.cells.map((cell) => ({ ...cell, label: classes.labels[cell.id] })),
  };

  const contactLists = curves.map((c) => {
    const out: VolumeContactRecord[][] = Array.from({ length: n }, () => []);
    for (const curve of c.values()) {
      const common = { length: curve.length, staircase: curve.staircase, edges: curve.edges, pieces: curve.pieces };
      out[curve.a - 1].push({ label: classes.labels[curve.b - 1], ...common });
      out[curve.b - 1].push({ label: classes.labels[curve.a - 1], ...common });
    }
    for (const list of out) list.sort((x, y) => x.label - y.label);
    return out;
  });
  const lateral = lateralContacts(faces, n, faceArea, classes.labels);
  const lateralMin = Math.max(...minContacts) ** 2;

  const voxelVolume = sx * sy * sz;
  let missing = 0;
  let touching = 0;
  const cells: VolumeCellRecord[] = classes.labels.map((label, id) => {
    const exclusion = exclusionOf(id, reaches, faces.volumeFaces[id + 1]);
    if (exclusion?.missingFrom.length) missing++;
    if (exclusion?.touchesFaces.length) touching++;
    const centroids = tallies.map((t, k) => (reaches[k][id] ? centroid(t, id + 1, faceArea, voxelSize) : null));
    const [cb, ca] = centroids;
    return {
      id,
      label,
      valid: analysis.cells.valid[id] === 1,
      scutoid: analysis.cells.scutoid[id] === 1,
      volume: classes.cellVoxels[id + 1] * voxelVolume,
      height: cb && ca ? Math.hypot(cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]) : null,
      centroids,
      areas: [areas[0][id], areas[1][id]],
      sides: analysis.cells.sides.map((s) => s[id]),
      neighbours: sets.map((s) => [...s[id]].map((j) => classes.labels[j]).sort((x, y) => x - y)),
      contacts: contactLists.map((lists) => lists[id]),
      won: analysis.cells.won[id],
      lost: analysis.cells.lost[id],
      transitions: analysis.cells.transitions[id],
      neighbours3D: analysis.cells.neighbours3D[id],
      lateralNeighbours: lateral[id].filter((c) => c.area >= lateralMin).map((c) => c.label),
      lateralContacts: lateral[id],
      exclusion,
    };
  });
  if (analysis.summary.validCells === 0)
    warnings.push('no valid cell: every cell touches a face of the volume or does not reach both the lumen and the outside');
  // Cells of an epithelium share more membrane with each other than with the lumen and the
  // outside; when they barely touch, background lines separate them (and join the outside).
  let lateralArea = 0;
  for (const list of lateral) for (const c of list) lateralArea += c.area / 2;
  const surfaceArea = areas[0].reduce((a, b) => a + b, 0) + areas[1].reduce((a, b) => a + b, 0);
  if (n > 1 && lateralArea < 0.1 * surfaceArea) {
    warnings.push(
      `cells barely touch each other (${lateralArea.toFixed(0)} µm² of shared interfaces for ${surfaceArea.toFixed(0)} µm² on the surfaces): a segmentation with lines of 0 between cells needs them removed (e.g. by dilating the labels) first`,
    );
  }

  const layers: VolumeSurfaceRecord[] = [0, 1].map((k) => {
    const { area, count } = reaching[k];
    return {
      name: LAYER_NAMES[k],
      faces: layerClass[k] === OUTSIDE ? 'outside' : 'lumen',
      cells: count,
      area,
      minContact: minContacts[k],
      contactPairs: curves[k].size,
    };
  });
  const background = backgroundRecord(classes, W, H, D);
  return {
    software: { name: 'tissue-sheet', version: options.version },
    kind: 'measured',
    inputs: {
      files: [{ name: file, bytes: fileBytes, format: 'tiff', pages }],
      volume: { width: W, height: H, depth: D, bitsPerSample, labels: n, voxels: W * H * D },
      voxelSize: { x: sx, y: sy, z: sz, source: voxelSize.source },
      voxelSizeDetail: voxelSize.detail,
      layers,
      background,
      options: {
        apical: options.apical ?? 'lumen',
        lumenLabel: options.lumenLabel ?? null,
        minContact: options.minContact ?? null,
        minContactSource: options.minContact === undefined ? 'default' : 'option',
        quartetFilter: options.quartetFilter ?? false,
      },
    },
    analyses: [measuredAnalysis],
    cells,
    exclusions: { touchesFaces: touching, missing, total: analysis.summary.excludedCells },
    quartetFilter: quartetRecord,
    comparison: null,
    warnings,
  };
}
