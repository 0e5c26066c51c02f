/**
 * A measured volume's per-cell CSV and figure (src/app/model/volumeCsv.ts, volumeFigure.ts)
 * against its JSON: the same cells, values and provenance, parsed back.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { compareVolume, measureVolume, type SurfaceMesh, type VolumeComparison, type VolumeMeasuredResult } from '../../src/core/measure';
import { parseCsv } from '../../src/core/sweep';
import { volumeCellCsv } from '../../src/app/model/volumeCsv';
import { intervalText, volumeFigure } from '../../src/app/model/volumeFigure';
import { checkStoredComparison } from '../../src/app/model/measureProject';
import { writeTiff } from '../measure/tiffWriter';
import { labelData, permutedLabels, tubeVolume, volumePages } from '../measure/volumes';

let result: VolumeMeasuredResult;
let comparison: VolumeComparison;

beforeAll(() => {
  const tube = tubeVolume({ width: 40, height: 40, depth: 24, voxel: { x: 0.5, y: 0.5, z: 1 }, inner: 5, outer: 8.5, sites: 20, seed: 3 });
  const labels = permutedLabels(20, 4, 3, 9);
  const bytes = writeTiff(volumePages(tube, labelData(tube, labels, 16), 16) as never);
  let meshes: { lumen: SurfaceMesh; outer: SurfaceMesh; spacing: number } | undefined;
  result = measureVolume({ name: 'tube.tif', read: () => bytes }, { voxelSize: tube.voxel, version: 'test', onSurfaceMeshes: (m) => (meshes = m) });
  const compared = compareVolume(result, { realizations: 3, seed: 1 }, meshes);
  expect(compared.comparison, compared.note).not.toBeNull();
  comparison = compared.comparison!;
});

describe("a measured volume's exports", () => {
  it('the per-cell CSV equals the JSON, cell by cell, with provenance lines', () => {
    const text = volumeCellCsv(result, comparison);
    const comments = text.split('\r\n').filter((l) => l.startsWith('#'));
    expect(comments[0]).toContain('tissue-sheet measured volume, per-cell table, written by tissue-sheet test');
    expect(comments.join('\n')).toContain('voxel 0.5 x 0.5 x 1 µm (option');
    expect(comments.join('\n')).toContain(`model (Voronoi ${comparison.bestK}, exact; seed 1, n = 3)`);
    const [header, ...rows] = parseCsv(
      text
        .split('\r\n')
        .filter((l) => !l.startsWith('#'))
        .join('\r\n'),
    ).records;
    expect(rows.length).toBe(result.cells.length);
    const col = (name: string) => header.indexOf(name);
    rows.forEach((row, k) => {
      const cell = result.cells[k];
      expect(Number(row[col('label')])).toBe(cell.label);
      expect(row[col('valid')]).toBe(cell.valid ? '1' : '0');
      expect(row[col('excluded_because')]).toBe(cell.exclusion?.reason ?? '');
      expect(row[col('scutoid')]).toBe(cell.scutoid ? '1' : '0');
      expect([Number(row[col('sides_basal')]), Number(row[col('sides_apical')])]).toEqual(cell.sides);
      expect([Number(row[col('won')]), Number(row[col('lost')]), Number(row[col('transitions')]), Number(row[col('neighbours3D')])]).toEqual([
        cell.won,
        cell.lost,
        cell.transitions,
        cell.neighbours3D,
      ]);
      expect(Number(row[col('volume_um3')])).toBe(cell.volume);
      expect([Number(row[col('area_um2_basal')]), Number(row[col('area_um2_apical')])]).toEqual(cell.areas);
      if (cell.height === null) expect(row[col('height_um')]).toBe('');
      else expect(Number(row[col('height_um')])).toBe(cell.height);
      expect(row[col('neighbour_labels_basal')].split(' ').filter(Boolean).map(Number)).toEqual(cell.neighbours[0]);
      expect(row[col('neighbour_labels_apical')].split(' ').filter(Boolean).map(Number)).toEqual(cell.neighbours[1]);
      expect(row[col('lateral_neighbour_labels')].split(' ').filter(Boolean).map(Number)).toEqual(cell.lateralNeighbours);
    });
    // The headline recomputed from the CSV.
    const valid = rows.filter((r) => r[col('valid')] === '1');
    expect((100 * valid.filter((r) => r[col('scutoid')] === '1').length) / valid.length).toBeCloseTo(result.analyses[0].summary.percentScutoids, 12);
  });

  it('the figure shows both surfaces, the model on its seeded side, and the model statistics with CI and n', () => {
    const figure = volumeFigure(result, comparison);
    expect(figure.series.map((s) => s.label)).toEqual([
      'measured basal (faces the outside)',
      'measured apical (faces the lumen)',
      `model Voronoi ${comparison.bestK}, ${comparison.geometry.seededLayer} (seeded), mean of 3 realizations`,
    ]);
    figure.series[0].points.forEach((p, c) => {
      const f = result.analyses[0].summary.perSurface[0].polygonDistribution[c];
      if (Number.isFinite(f)) expect(p.y).toBeCloseTo(100 * f, 12);
    });
    const notes = figure.notes.join('\n');
    expect(notes).toContain(`${intervalText(comparison.model.percentScutoids, 1)} % scutoids`);
    expect(notes).toContain('n = 3 realizations');
    expect(notes).toContain('an open piece: the fitted tube');
    expect(intervalText({ mean: 2, ci95: [Number.NaN, Number.NaN] }, 1)).toBe('2.0 (one realization, no CI)');
  });

  it('a result with no valid cell, read back from its JSON (NaN became null): the CSV and the figure say "n/a", never NaN, and do not throw', () => {
    const copy = JSON.parse(JSON.stringify(result)) as VolumeMeasuredResult;
    const summary = copy.analyses[0].summary as unknown as Record<string, unknown>;
    for (const key of ['percentScutoids', 'meanTransitions', 'meanNeighbours3D']) summary[key] = null;
    summary.validCells = 0;
    summary.scutoids = 0;
    const text = volumeCellCsv(copy, null);
    expect(text).toContain('# % scutoids n/a (0 of 0 valid cells; one tissue)');
    const notes = volumeFigure(copy, null).notes.join('\n');
    expect(notes).toContain('no % scutoids (no valid cell) (0 of 0 valid cells, one tissue), n/a transitions and n/a 3D neighbours per cell');
    expect(text + notes).not.toMatch(/NaN/);
  });

  it('a comparison kept in a project file is checked before it is shown: the real one passes, a tampered one is refused naming the field', () => {
    const stored = JSON.parse(JSON.stringify(comparison)) as Record<string, unknown>;
    expect(() => checkStoredComparison(stored, 'volume', 'c')).not.toThrow();
    expect(() => checkStoredComparison(null, 'volume', 'c')).not.toThrow();
    // A JSON copy with one field edited (undefined: removed), as a person editing the file would.
    const tampered = (path: string, value: unknown) => {
      const copy = JSON.parse(JSON.stringify(comparison)) as Record<string, unknown>;
      const keys = path.split('.');
      const parent = keys.slice(0, -1).reduce((o, k) => o[k] as Record<string, unknown>, copy);
      if (value === undefined) delete parent[keys[keys.length - 1]];
      else parent[keys[keys.length - 1]] = value;
      return () => checkStoredComparison(copy, 'volume', 'c');
    };
    expect(tampered('model.percentScutoids.mean', '12')).toThrow('c.model.percentScutoids.mean: expected a number');
    expect(tampered('model.transitions.ci95', [1])).toThrow('c.model.transitions.ci95: expected two numbers');
    expect(tampered('geometry.kind', 'blob')).toThrow('c.geometry.kind');
    expect(tampered('bestK', 99)).toThrow('c.candidates: expected a list with the best k (99)');
    expect(tampered('summary', undefined)).toThrow('c.summary.perSurface');
    expect(() => checkStoredComparison([], 'layers', 'c')).toThrow('c: expected the model comparison or null');
  });
});
