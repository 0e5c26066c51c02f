/**
 * The measured tissue's per-cell CSV (issue 26): one row per label, what the page shows when a
 * cell is picked: valid (and why not), scutoid, sides, area (µm²) and neighbour labels per layer,
 * neighbours won and lost from basal to apical, transitions and 3D neighbours. Provenance comment
 * lines first (read with pandas `comment="#"`): version, the files and which is basal, pixel size,
 * minimum contact, surface ratio, the method (pixel-based adjacency of the label images).
 */
import { formatCsv } from '../../core/sweep';
import type { MeasuredResult } from '../../core/measure';
import { summaryNumber } from '../../core/analysis/summaryText';

/** The per-cell CSVs' statistics columns for surfaces or layers `names`: sides, won to neighbours3D, areas. */
export function statisticsColumns(names: string[]): string[] {
  return [...names.map((n) => `sides_${n}`), 'won', 'lost', 'transitions', 'neighbours3D', ...names.map((n) => `area_um2_${n}`)];
}

export function measuredCellCsv(result: MeasuredResult): string {
  const names = result.inputs.layers.map((l) => l.name.replace(/\s+/g, '_'));
  const header = ['label', 'valid', 'excluded_because', 'scutoid', ...statisticsColumns(names), ...names.map((n) => `neighbour_labels_${n}`)];
  const rows = result.cells.map((cell) => [
    cell.label,
    cell.valid ? 1 : 0,
    cell.exclusion?.reason ?? '',
    cell.scutoid ? 1 : 0,
    ...cell.sides,
    cell.won,
    cell.lost,
    cell.transitions,
    cell.neighbours3D,
    ...cell.areas.map((a) => Math.round(a * 1000) / 1000),
    ...cell.neighbours.map((n) => n.join(' ')),
  ]);
  const s = result.analyses[0].summary;
  const layers = result.inputs.layers.map((l) => `${l.name}: ${l.file}${result.inputs.files.length === 1 ? ` page ${l.page + 1}` : ''}`).join('; ');
  const comments = [
    `tissue-sheet measured tissue, per-cell table, written by tissue-sheet ${result.software.version}`,
    `method: pixel-based adjacency of the label images (measured); contacts shorter than ${result.analyses[0].minContactLength.toPrecision(3)} µm ignored`,
    `layers (the first is basal): ${layers}; pixel size ${result.inputs.pixelSize.value} µm; surface ratio ${result.surfaceRatio.value.toFixed(4)} (from the ${result.surfaceRatio.source})`,
    `% scutoids ${summaryNumber(s.percentScutoids, 2)} (${s.scutoids} of ${s.validCells} valid cells; one tissue); options: ${JSON.stringify(result.inputs.options)}`,
  ].map((line) => `# ${line.replace(/[\r\n]+/g, ' ')}\r\n`);
  return comments.join('') + formatCsv(header, rows);
}
