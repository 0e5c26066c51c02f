/**
 * A measured volume beside the model of the same geometry, as a figure (chartSvg.ts, the app's
 * figure machinery; pure): the measured basal and apical polygon distributions as bars, the best
 * model's mean distribution on its seeded (lumen-side) surface as a dashed line; the notes give
 * the measured values beside the model's mean and 95 % CI over its realizations, and the
 * geometry the model ran on. Also the words for that geometry and for an interval, shared with
 * the page's table.
 */
import type { Interval, VolumeComparison, VolumeMeasuredResult } from '../../core/measure';
import { SIDE_LABELS } from '../../view/sideColors';
import type { ChartSeries, ChartSpec } from './chartSvg';
import { scutoidsText, summaryNumber } from '../../core/analysis/summaryText';

const COLORS = ['#1f5fa8', '#c0392b'];

/** "12.3 (95 % CI 10.1 to 14.5)", or with one realization "12.3 (one realization, no CI)". */
export function intervalText(interval: Interval, digits: number): string {
  const [lo, hi] = interval.ci95;
  return Number.isFinite(lo) && Number.isFinite(hi)
    ? `${interval.mean.toFixed(digits)} (95 % CI ${lo.toFixed(digits)} to ${hi.toFixed(digits)})`
    : `${interval.mean.toFixed(digits)} (one realization, no CI)`;
}

/** What the model ran on, in words. */
export function geometryText(comparison: VolumeComparison): string {
  const g = comparison.geometry;
  if (g.kind === 'tube') {
    return `an open piece: the fitted tube, radius ${g.innerRadius.toFixed(2)} to ${g.outerRadius.toFixed(2)} µm, ${g.length.toFixed(2)} µm long, seeded on the ${g.seededLayer} side (${g.seededCells} cells), thickness ${g.thickness.mean.toFixed(2)} ± ${g.thickness.sd.toFixed(2)} µm`;
  }
  return `a closed shell: the tissue's own surfaces as meshes (${g.seeded.triangles} and ${g.other.triangles} triangles), seeded on the ${g.seededLayer} side (${g.seededCells} cells); ${g.projection.alongNormal} sites carried along the normal to the other surface, ${g.projection.parallel} placed on the parallel surface; thickness ${g.thickness.mean.toFixed(2)} ± ${g.thickness.sd.toFixed(2)} µm`;
}

export function volumeFigure(
  result: VolumeMeasuredResult,
  comparison: VolumeComparison | null,
): Pick<ChartSpec, 'title' | 'xLabel' | 'yLabel' | 'series' | 'notes' | 'xTicks' | 'yRange'> {
  const s = result.analyses[0].summary;
  const series: ChartSeries[] = result.inputs.layers.map((layer, k) => ({
    label: `measured ${layer.name} (faces the ${layer.faces})`,
    color: COLORS[k],
    style: 'bars' as const,
    labels: 1,
    points: s.perSurface[k].polygonDistribution.map((f, c) => ({ x: c + 3, y: f === null || !Number.isFinite(f) ? Number.NaN : 100 * f })),
  }));
  if (comparison) {
    const seeded = comparison.geometry.seededLayer;
    series.push({
      label: `model Voronoi ${comparison.bestK}, ${seeded} (seeded), mean of ${comparison.realizations} realizations`,
      color: '#111',
      style: 'line',
      dashed: true,
      points: comparison.candidates[comparison.bestK - 1].polygonDistribution.map((f, c) => ({ x: c + 3, y: 100 * f })),
    });
  }
  const max = Math.max(...series.flatMap((x) => x.points.map((p) => p.y)).filter(Number.isFinite));
  const v = result.inputs.voxelSize;
  const notes = [
    `Measured (${result.inputs.files[0].name}, voxel ${v.x} x ${v.y} x ${v.z} µm): ${scutoidsText(s.percentScutoids)} (${s.scutoids} of ${s.validCells} valid cells, one tissue), ${summaryNumber(s.meanTransitions, 2)} transitions and ${summaryNumber(s.meanNeighbours3D, 2)} 3D neighbours per cell.`,
  ];
  if (comparison) {
    const m = comparison.model;
    notes.push(
      `Model (Voronoi ${comparison.bestK}, exact; n = ${comparison.realizations} realizations, mean and 95 % CI): ${intervalText(m.percentScutoids, 1)} % scutoids, ${intervalText(m.transitions, 2)} transitions, ${intervalText(m.neighbours3D, 2)} 3D neighbours.`,
      `Model geometry: ${geometryText(comparison)}.`,
    );
  } else notes.push('No model comparison.');
  return {
    title: 'Measured volume and the model of the same geometry: polygon distribution',
    xLabel: 'sides (cells with n sides)',
    yLabel: '% of valid cells',
    xTicks: SIDE_LABELS.map((label, k) => ({ x: k + 3, label })),
    yRange: [0, Math.min(100, Math.ceil((Number.isFinite(max) ? max : 50) * 1.15))],
    series,
    notes,
  };
}
