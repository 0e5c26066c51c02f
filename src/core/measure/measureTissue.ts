/**
 * Measures a segmented tissue (docs/measure.md): decodes one layer at a time, counts its
 * contacts, then builds one analysis input per layer over the union of labels and runs the
 * same analysis as a simulated stack (analyzeSurfaces) on it.
 */
import { adjacencyFromLists, analysisRecord, analyzeSurfaces, labMinBoundaryLength, withMinBoundaryLength, type SurfaceAdjacency } from '../analysis';
import { BORDER_EXCLUDED } from '../border';
import { BORDER_NAMES, countContacts, type LayerContacts } from './contacts';
import { MeasureInputError } from './errors';
import type { LabelPixels } from './labelImage';
import { decodeLayer, planLayers, type LabelFileInput, type LayerPlan } from './layerPlan';
import type { BorderTouch, CellExclusion, ContactRecord, MeasuredAnalysis, MeasuredCellRecord, MeasuredLayerRecord, MeasuredResult } from './measuredResult';

export interface MeasureOptions {
  /** µm per pixel; overrides the files' metadata. */
  readonly pixelSize?: number;
  readonly periodicX?: boolean;
  /** Shortest contact (µm) that makes two cells neighbours; default in docs/measure.md. */
  readonly minContact?: number;
  /** Apical over basal size; default from the layers' widths or areas. */
  readonly surfaceRatio?: number;
  readonly version: string;
  /** Progress lines (optional). */
  readonly onProgress?: (line: string) => void;
  /**
   * Called with each layer's decoded labels (layer index, basal first) once its contacts are
   * counted, before the next layer is decoded: the result holds no pixels, so a caller that
   * draws the tissue keeps (or reduces) them here. The array is not used by the measurement
   * afterwards.
   */
  readonly onLayerPixels?: (layer: number, pixels: LabelPixels) => void;
}

const now = () => performance.now();

export function measureTissue(files: LabelFileInput[], options: MeasureOptions): MeasuredResult {
  const start = now();
  const periodicX = options.periodicX ?? false;
  const plan = planLayers(files, options.pixelSize);
  let readMs = now() - start;
  let contactsMs = 0;

  const contacts: LayerContacts[] = [];
  let bytes: Uint8Array | null = null;
  let bytesOf = -1;
  for (const layer of plan.layers) {
    const t0 = now();
    if (bytesOf !== layer.file) {
      bytes = null; // let the previous file go before reading the next
      bytes = files[layer.file].read();
      bytesOf = layer.file;
    }
    const pixels = decodeLayer(bytes!, plan, layer);
    const t1 = now();
    const counted = countContacts(pixels, periodicX);
    contactsMs += now() - t1;
    readMs += t1 - t0;
    const file = plan.files[layer.file].name;
    if (counted.labels === 0) {
      throw new MeasureInputError(file, `${plan.files.length === 1 ? `page ${layer.page + 1}: ` : ''}no labels (every pixel is 0)`);
    }
    contacts.push(counted);
    options.onLayerPixels?.(contacts.length - 1, pixels);
    options.onProgress?.(
      `${layer.name}: ${file}${plan.files.length === 1 ? ` page ${layer.page + 1}` : ''}, ${pixels.width} x ${pixels.height}, ${counted.labels} labels, ${counted.edges.size} contacts`,
    );
  }
  bytes = null;

  const t2 = now();
  const result = assemble(plan, contacts, options, periodicX);
  const analysisMs = now() - t2;
  return { ...result, timings: { readMs, contactsMs, analysisMs, totalMs: now() - start } };
}

function assemble(plan: LayerPlan, contacts: LayerContacts[], options: MeasureOptions, periodicX: boolean): Omit<MeasuredResult, 'timings'> {
  const p = plan.pixelSize.value;
  const warnings = [...plan.warnings];
  const K = contacts.length;

  // Dense ids: every label present on any layer, ascending.
  const space = Math.max(...contacts.map((c) => c.labelSpace));
  const present = new Uint8Array(space);
  for (const c of contacts) for (let v = 1; v < c.labelSpace; v++) if (c.pixels[v] > 0) present[v] = 1;
  const labels: number[] = [];
  const idOf = new Int32Array(space).fill(-1);
  for (let v = 1; v < space; v++) if (present[v]) idOf[v] = labels.push(v) - 1;
  const count = labels.length;

  const surfaces: SurfaceAdjacency[] = contacts.map((c, k) => layerSurface(c, plan.layers[k].name, idOf, count, p));
  contacts.forEach((c, k) => {
    if (c.edges.size === 0) {
      warnings.push(
        `${plan.layers[k].name} (${plan.files[plan.layers[k].file].name}): no two labels touch; label images with lines of 0 between cells need the lines removed (e.g. by dilating the labels) first`,
      );
    }
  });

  const basal = contacts[0];
  let basalPixels = 0;
  for (let v = 1; v < basal.labelSpace; v++) basalPixels += basal.pixels[v];
  const minContactLength = options.minContact ?? labMinBoundaryLength(basalPixels * p * p, basal.labels);
  const analysis = analyzeSurfaces(surfaces.map((s) => withMinBoundaryLength(s, minContactLength)));
  const cellStats = analysis.cells;

  const record = analysisRecord('labels', minContactLength, analysis);
  const measuredAnalysis: MeasuredAnalysis = {
    ...record,
    method: 'labels',
    // The same per-cell statistics as a simulated result's, with each cell's own label.
    cells: record.cells.map((cell) => ({ ...cell, label: labels[cell.id] })),
  };

  // Per-cell records with original labels.
  const neighbourLists: ContactRecord[][][] = contacts.map((c) => contactLists(c, idOf, count, p));
  let missing = 0;
  let touching = 0;
  const cells: MeasuredCellRecord[] = labels.map((label, id) => {
    const exclusion = exclusionOf(label, contacts, plan);
    if (exclusion?.missingFrom.length) missing++;
    if (exclusion?.touchesBorder.length) touching++;
    const perLayer = neighbourLists.map((lists) => lists[id]);
    return {
      id,
      label,
      valid: cellStats.valid[id] === 1,
      scutoid: cellStats.scutoid[id] === 1,
      areas: contacts.map((c) => (label < c.labelSpace ? c.pixels[label] : 0) * p * p),
      sides: cellStats.sides.map((s) => s[id]),
      neighbours: perLayer.map((list) => list.filter((x) => x.length >= minContactLength).map((x) => x.label)),
      contacts: perLayer,
      won: cellStats.won[id],
      lost: cellStats.lost[id],
      transitions: cellStats.transitions[id],
      neighbours3D: cellStats.neighbours3D[id],
      exclusion,
    };
  });
  if (analysis.summary.validCells === 0) warnings.push('no valid cell: every cell touches a non-periodic border or is missing from a layer');

  const layers: MeasuredLayerRecord[] = plan.layers.map((layer, k) => {
    let labelled = 0;
    for (let v = 1; v < contacts[k].labelSpace; v++) labelled += contacts[k].pixels[v];
    return {
      name: layer.name,
      file: plan.files[layer.file].name,
      page: layer.page,
      width: layer.header.width,
      height: layer.header.height,
      bitsPerSample: layer.header.bitsPerSample,
      labels: contacts[k].labels,
      labelledPixels: labelled,
      contactPairs: contacts[k].edges.size,
    };
  });
  const first = layers[0];
  const last = layers[K - 1];
  const surfaceRatio =
    options.surfaceRatio !== undefined
      ? { value: options.surfaceRatio, source: 'option' as const }
      : first.width !== last.width
        ? { value: last.width / first.width, source: 'widths' as const }
        : { value: last.labelledPixels / first.labelledPixels, source: 'areas' as const };

  return {
    // software first: the CLI recognizes its own results by how they start.
    software: { name: 'tissue-sheet', version: options.version },
    kind: 'measured',
    inputs: {
      files: plan.files.map((f) => ({ name: f.name, bytes: f.bytes, format: f.header.format, pages: f.header.pages.length })),
      layers,
      pixelSize: plan.pixelSize,
      layerSpacing: plan.layerSpacing,
      options: {
        periodicX,
        minContact: options.minContact ?? null,
        minContactSource: options.minContact === undefined ? 'default' : 'option',
      },
    },
    analyses: [measuredAnalysis],
    cells,
    exclusions: { touchesBorder: touching, missing, total: analysis.summary.excludedCells },
    surfaceRatio,
    comparison: null,
    warnings,
  };
}

/** One layer as analysis input over all `count` cells: contact lengths in µm, areas in µm². */
function layerSurface(c: LayerContacts, name: string, idOf: Int32Array, count: number, p: number): SurfaceAdjacency {
  const lists: number[][] = Array.from({ length: count }, () => []);
  const lengths: number[][] = Array.from({ length: count }, () => []);
  for (const [key, edges] of c.edges) {
    const a = idOf[Math.floor(key / 65536)];
    const b = idOf[key % 65536];
    lists[a].push(b);
    lengths[a].push(edges * p);
    lists[b].push(a);
    lengths[b].push(edges * p);
  }
  const areas = new Float64Array(count);
  const border = new Uint8Array(count);
  idOf.forEach((id, label) => {
    if (id < 0) return;
    const pixels = label < c.labelSpace ? c.pixels[label] : 0;
    areas[id] = pixels * p * p;
    // Missing from this layer or touching its open border: left out of the statistics.
    border[id] = pixels === 0 ? BORDER_EXCLUDED : c.border[label];
  });
  return adjacencyFromLists(lists, lengths, areas, border, name);
}

/** Every contact of every cell on one layer, by original label, ascending. */
function contactLists(c: LayerContacts, idOf: Int32Array, count: number, p: number): ContactRecord[][] {
  const out: ContactRecord[][] = Array.from({ length: count }, () => []);
  for (const [key, edges] of c.edges) {
    const a = Math.floor(key / 65536);
    const b = key % 65536;
    out[idOf[a]].push({ label: b, edges, length: edges * p });
    out[idOf[b]].push({ label: a, edges, length: edges * p });
  }
  for (const list of out) list.sort((x, y) => x.label - y.label);
  return out;
}

function exclusionOf(label: number, contacts: LayerContacts[], plan: LayerPlan): CellExclusion | null {
  const missingFrom: number[] = [];
  const touchesBorder: BorderTouch[] = [];
  contacts.forEach((c, k) => {
    if (label >= c.labelSpace || c.pixels[label] === 0) missingFrom.push(k);
    else if (c.border[label] !== 0) {
      touchesBorder.push({ layer: k, sides: BORDER_NAMES.filter(([bit]) => c.border[label] & bit).map(([, n]) => n) as BorderTouch['sides'] });
    }
  });
  if (missingFrom.length === 0 && touchesBorder.length === 0) return null;
  const reasons = [
    ...touchesBorder.map((t) => `touches the ${t.sides.join(' and ')} border${t.sides.length > 1 ? 's' : ''} on ${plan.layers[t.layer].name}`),
    ...(missingFrom.length ? [`missing from ${missingFrom.map((k) => plan.layers[k].name).join(', ')}`] : []),
  ];
  return { missingFrom, touchesBorder, reason: reasons.join('; ') };
}
