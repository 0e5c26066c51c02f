/**
 * A measured volume's per-cell CSV (docs/app.md, "Measure a volume"): one row per label, what
 * the page shows when a cell is picked: valid (and why not), scutoid, sides, area (µm²) and
 * neighbour labels on the basal and apical surfaces, neighbours won and lost from basal to
 * apical, transitions, 3D neighbours, volume (µm³), height (µm) and lateral neighbours.
 * Numbers at full precision (they read back equal to the JSON's). Provenance comment lines first (read with pandas `comment="#"`): version, the file, voxel size
 * and where it came from, which background each surface faces, minimum contacts, the method.
 */
import { formatCsv } from '../../core/sweep';
import type { VolumeComparison, VolumeMeasuredResult } from '../../core/measure';
import { summaryNumber } from '../../core/analysis/summaryText';

export function volumeCellCsv(result: VolumeMeasuredResult, comparison: VolumeComparison | null = null): string {
  const header = [
    'label',
    'valid',
    'excluded_because',
    'scutoid',
    'sides_basal',
    'sides_apical',
    'won',
    'lost',
    'transitions',
    'neighbours3D',
    'volume_um3',
    'height_um',
    'area_um2_basal',
    'area_um2_apical',
    'neighbour_labels_basal',
    'neighbour_labels_apical',
    'lateral_neighbour_labels',
  ];
  const rows = result.cells.map((cell) => [
    cell.label,
    cell.valid ? 1 : 0,
    cell.exclusion?.reason ?? '',
    cell.scutoid ? 1 : 0,
    cell.sides[0],
    cell.sides[1],
    cell.won,
    cell.lost,
    cell.transitions,
    cell.neighbours3D,
    cell.volume,
    cell.height === null ? '' : cell.height,
    cell.areas[0],
    cell.areas[1],
    cell.neighbours[0].join(' '),
    cell.neighbours[1].join(' '),
    cell.lateralNeighbours.join(' '),
  ]);
  const s = result.analyses[0].summary;
  const { voxelSize: v, layers, files } = result.inputs;
  const m = comparison?.model;
  const comments = [
    `tissue-sheet measured volume, per-cell table, written by tissue-sheet ${result.software.version}`,
    `file: ${files[0].name}; voxel ${v.x} x ${v.y} x ${v.z} µm (${v.source}: ${result.inputs.voxelSizeDetail})`,
    `method: contact curves on the voxel surfaces, lengths in µm along the curve (measured); ` +
      layers.map((l) => `${l.name} faces the ${l.faces}, contacts shorter than ${l.minContact.toPrecision(3)} µm ignored`).join('; '),
    `% scutoids ${summaryNumber(s.percentScutoids, 2)} (${s.scutoids} of ${s.validCells} valid cells; one tissue); options: ${JSON.stringify(result.inputs.options)}`,
    m
      ? `model (Voronoi ${comparison!.bestK}, exact; seed ${comparison!.seed}, n = ${comparison!.realizations}): ${m.percentScutoids.mean.toFixed(2)} % scutoids (95 % CI ${m.percentScutoids.ci95.map((x) => x.toFixed(2)).join(' to ')})`
      : 'no model comparison',
  ].map((line) => `# ${line.replace(/[\r\n]+/g, ' ')}\r\n`);
  return comments.join('') + formatCsv(header, rows);
}
