/**
 * `measure --volume` against volumes built by the model's own construction (volumes.ts), whose
 * neighbour sets and contact lengths on both surfaces are known exactly.
 *
 * A pair is checked where the exact answer is clear-cut at every depth the voxel surface spans
 * (its exact contact length at both bracketing depths at least min-contact + MARGIN, or at most
 * min-contact - MARGIN); pairs within MARGIN of the threshold are left out and counted. MARGIN
 * is about one voxel diagonal: how far a contact curve's end can move when it is voxelized.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { compareVolume, fitCircle, interval, measureVolume, smallestEigenvector, type VolumeMeasuredResult } from '../../src/core/measure';
import { writeTiff } from './tiffWriter';
import { labelData, permutedLabels, shellVolume, tubeVolume, volumePages, type SyntheticVolume } from './volumes';

const input = (bytes: Uint8Array, name = 'volume.tif') => ({ name, read: () => bytes });

function tiffOf(volume: SyntheticVolume, labels: number[], bits: 8 | 16 | 32, lumenLabel = 0): Uint8Array {
  return writeTiff(volumePages(volume, labelData(volume, labels, bits, lumenLabel), bits) as never);
}

interface Agreement {
  checked: number;
  ambiguous: number;
  wrong: string[];
  /** Clear-cut pairs a staircase length (voxel edges) would get wrong at the same threshold. */
  staircaseWrong: number;
}

/**
 * Per valid cell and layer, the measured neighbours against the exact ones. `layerOf` says
 * which exact surface (outer or inner) each layer is.
 */
function agreement(
  result: VolumeMeasuredResult,
  volume: SyntheticVolume,
  labels: number[],
  margin: number,
  layerOf: ('outer' | 'inner')[] = ['outer', 'inner'],
): Agreement {
  const n = volume.sites;
  const siteOf = new Map(labels.map((l, k) => [l, k]));
  const out: Agreement = { checked: 0, ambiguous: 0, wrong: [], staircaseWrong: 0 };
  for (const cell of result.cells) {
    if (!cell.valid) continue;
    const i = siteOf.get(cell.label)!;
    for (let k = 0; k < 2; k++) {
      const exact = volume.exact[layerOf[k]];
      const threshold = result.inputs.layers[k].minContact;
      const measured = new Set(cell.neighbours[k]);
      const staircase = new Map(cell.contacts[k].map((c) => [c.label, c.staircase]));
      for (let j = 0; j < n; j++) {
        if (j === i) continue;
        const key = i < j ? i * n + j : j * n + i;
        const e0 = exact[0].get(key) ?? 0;
        const e1 = exact[1].get(key) ?? 0;
        const lo = Math.min(e0, e1);
        const hi = Math.max(e0, e1);
        const sure = lo >= threshold + margin;
        const sureNot = hi <= threshold - margin || (hi === 0 && threshold < margin && !nearlyTouching(exact, n, i, j, margin));
        if (!sure && !sureNot) {
          out.ambiguous++;
          continue;
        }
        out.checked++;
        const has = measured.has(labels[j]);
        if (sure !== has)
          out.wrong.push(
            `cell ${cell.label} layer ${k}: ${labels[j]} exact ${e0.toFixed(2)}..${e1.toFixed(2)} µm, threshold ${threshold.toFixed(2)}, measured ${has}`,
          );
        if (sure !== (staircase.get(labels[j]) ?? 0) >= threshold) out.staircaseWrong++;
      }
    }
  }
  return out;
}

/**
 * Cells i, j that do not touch but are separated only by a contact shorter than `margin`
 * between two common neighbours c, d (near a four-cell vertex): voxelized, they may touch.
 */
function nearlyTouching(exact: Map<number, number>[], n: number, i: number, j: number, margin: number): boolean {
  const len = (p: number, q: number) => Math.max(exact[0].get(p < q ? p * n + q : q * n + p) ?? 0, exact[1].get(p < q ? p * n + q : q * n + p) ?? 0);
  const common: number[] = [];
  for (let c = 0; c < n; c++) if (c !== i && c !== j && len(i, c) > 0 && len(j, c) > 0) common.push(c);
  for (const c of common) for (const d of common) if (c < d && len(c, d) < margin) return true;
  return false;
}

const SHELL = { voxel: { x: 0.5, y: 0.5, z: 0.75 }, a: 24, b: 18, c: 15, h: 6, sites: 60, seed: 5, margin: 2 };
const TUBE = { width: 80, height: 80, depth: 60, voxel: { x: 0.5, y: 0.5, z: 1 }, inner: 10, outer: 18, sites: 40, seed: 3 };

let shell: SyntheticVolume;
let tube: SyntheticVolume;
let shellLabels: number[];
let shellResult: VolumeMeasuredResult;

beforeAll(() => {
  shell = shellVolume(SHELL);
  tube = tubeVolume(TUBE);
  shellLabels = Array.from({ length: shell.sites }, (_, k) => k + 1);
  shellResult = measureVolume(input(tiffOf(shell, shellLabels, 16)), { voxelSize: shell.voxel, version: 'test' });
}, 60_000);

describe('measure --volume: a closed ellipsoidal shell (cyst)', () => {
  const margin = 1.1;

  it('finds the outside, one lumen, every cell valid, and the exact neighbours on both surfaces', () => {
    const r = shellResult;
    expect(r.inputs.background).toMatchObject({ lumenComponents: 1, pockets: 0, labelledLumenVoxels: 0 });
    expect(r.inputs.layers.map((l) => [l.name, l.faces])).toEqual([
      ['basal', 'outside'],
      ['apical', 'lumen'],
    ]);
    expect(r.cells.map((c) => c.label)).toEqual(shellLabels);
    expect(r.analyses[0].summary.validCells).toBe(shell.sites);
    const a = agreement(r, shell, shellLabels, margin);
    expect(a.wrong).toEqual([]);
    expect(a.checked).toBeGreaterThan(2 * 60 * 5);
    // Scutoids: the ellipsoid's shape changes between depths, so some neighbour sets differ.
    expect(r.analyses[0].summary.scutoids).toBeGreaterThan(0);
    for (const cell of r.cells) expect(cell.scutoid).toBe(cell.neighbours[0].join() !== cell.neighbours[1].join());
  });

  it('measures contact curves by their length, not their voxel staircase', () => {
    const n = shell.sites;
    let worst = 0;
    let staircaseExcess = 0;
    let pairs = 0;
    for (const cell of shellResult.cells) {
      for (const [k, surface] of [
        [0, 'outer'],
        [1, 'inner'],
      ] as const) {
        for (const c of cell.contacts[k]) {
          const i = cell.label - 1;
          const j = c.label - 1;
          const key = i < j ? i * n + j : j * n + i;
          const e0 = shell.exact[surface][0].get(key) ?? 0;
          const e1 = shell.exact[surface][1].get(key) ?? 0;
          if (Math.min(e0, e1) < 2) continue; // the long curves: their length, not their ends, dominates
          const exact = 0.5 * (e0 + e1);
          worst = Math.max(worst, Math.abs(c.length - exact) - 0.5 * Math.abs(e0 - e1));
          staircaseExcess += c.staircase / exact;
          pairs++;
        }
      }
    }
    expect(pairs).toBeGreaterThan(300);
    expect(worst).toBeLessThan(1.0); // about one voxel diagonal (1.03 µm)
    expect(staircaseExcess / pairs).toBeGreaterThan(1.3); // what counting voxel edges would give
  });

  it('applies a min-contact well above the voxel size to the true lengths (staircase lengths would fail)', () => {
    const r = measureVolume(input(tiffOf(shell, shellLabels, 16)), { voxelSize: shell.voxel, minContact: 3.5, version: 'test' });
    expect(r.inputs.options).toMatchObject({ minContact: 3.5, minContactSource: 'option' });
    expect(r.inputs.layers.map((l) => l.minContact)).toEqual([3.5, 3.5]);
    expect(r.analyses[0].minContactLength).toBe(3.5);
    const a = agreement(r, shell, shellLabels, margin);
    expect(a.wrong).toEqual([]);
    expect(a.checked).toBeGreaterThan(2 * 60 * 5);
    expect(a.staircaseWrong).toBeGreaterThan(10);
  });

  it('records the default min-contact per surface: 6 / 102.4 of the mean cell diameter there', () => {
    for (const layer of shellResult.inputs.layers) {
      expect(layer.minContact).toBeCloseTo((6 / Math.sqrt((512 * 4096) / 200)) * Math.sqrt(layer.area / layer.cells), 10);
    }
    expect(shellResult.inputs.options).toMatchObject({ minContact: null, minContactSource: 'default' });
    expect(shellResult.analyses[0].minContactLength).toBe(shellResult.inputs.layers[0].minContact);
  });

  it('reports cell volumes (voxels x voxel volume), areas near the exact ones, heights and lateral neighbours', () => {
    const voxels = new Map<number, number>();
    for (const s of shell.site) if (s >= 0) voxels.set(s, (voxels.get(s) ?? 0) + 1);
    const { x, y, z } = shell.voxel;
    let basal = 0;
    let apical = 0;
    for (const cell of shellResult.cells) {
      expect(cell.volume).toBeCloseTo(voxels.get(cell.label - 1)! * x * y * z, 9);
      basal += cell.areas[0];
      apical += cell.areas[1];
      expect(cell.height).toBeGreaterThan(SHELL.h * 0.6);
      expect(cell.height).toBeLessThan(SHELL.h * 1.6);
      // Every neighbour on a surface shares an interface with the cell in 3D.
      for (const label of [...cell.neighbours[0], ...cell.neighbours[1]]) expect(cell.lateralContacts.map((c) => c.label)).toContain(label);
      expect(cell.lateralNeighbours.length).toBeGreaterThanOrEqual(Math.max(cell.sides[0], cell.sides[1]) - 1);
    }
    // Areas: each cell within 8 % of its exact restricted-Voronoi area, the surfaces within 2.5 %
    // (the voxel faces alone would be up to √3 too large).
    const exact = shell.exactAreas!;
    let basalExact = 0;
    let apicalExact = 0;
    for (const cell of shellResult.cells) {
      const [outer, inner] = [exact.outer[cell.label - 1], exact.inner[cell.label - 1]];
      basalExact += outer;
      apicalExact += inner;
      expect(Math.abs(cell.areas[0] / outer - 1)).toBeLessThan(0.08);
      expect(Math.abs(cell.areas[1] / inner - 1)).toBeLessThan(0.08);
    }
    expect(Math.abs(basal / basalExact - 1)).toBeLessThan(0.025);
    expect(Math.abs(apical / apicalExact - 1)).toBeLessThan(0.025);
  });

  it('swaps the surfaces with apical: outside (layers stay basal, apical)', () => {
    const r = measureVolume(input(tiffOf(shell, shellLabels, 16)), { voxelSize: shell.voxel, apical: 'outside', version: 'test' });
    expect(r.inputs.layers.map((l) => [l.name, l.faces])).toEqual([
      ['basal', 'lumen'],
      ['apical', 'outside'],
    ]);
    expect(r.inputs.options.apical).toBe('outside');
    const a = agreement(r, shell, shellLabels, margin, ['inner', 'outer']);
    expect(a.wrong).toEqual([]);
    r.cells.forEach((cell, k) => {
      expect(cell.neighbours).toEqual([shellResult.cells[k].neighbours[1], shellResult.cells[k].neighbours[0]]);
      expect(cell.areas).toEqual([shellResult.cells[k].areas[1], shellResult.cells[k].areas[0]]);
    });
  });

  it('gives the same answer for permuted 16-bit and 32-bit labels (original labels reported)', () => {
    const byLabel = (r: VolumeMeasuredResult, labels: number[]) => {
      const site = new Map(labels.map((l, k) => [l, k]));
      return new Map(r.cells.map((c) => [site.get(c.label)!, c.neighbours.map((list) => list.map((l) => site.get(l)!).sort((p, q) => p - q))]));
    };
    const reference = byLabel(shellResult, shellLabels);
    for (const [bits, labels] of [
      [16, permutedLabels(shell.sites, 300, 997, 11)],
      [32, permutedLabels(shell.sites, 70_000, 1_000_003, 12)],
      [8, permutedLabels(shell.sites, 3, 4, 13)],
    ] as const) {
      const r = measureVolume(input(tiffOf(shell, labels, bits)), { voxelSize: shell.voxel, version: 'test' });
      expect(r.inputs.volume.bitsPerSample).toBe(bits);
      expect(r.cells.map((c) => c.label)).toEqual([...labels].sort((p, q) => p - q));
      expect(byLabel(r, labels)).toEqual(reference);
      expect(r.analyses[0].cells.map((c) => c.label)).toEqual(r.cells.map((c) => c.label));
    }
  });

  it('treats a labelled lumen (--lumen-label) as lumen, with the same neighbours', () => {
    const r = measureVolume(input(tiffOf(shell, shellLabels, 16, 4000)), { voxelSize: shell.voxel, lumenLabel: 4000, version: 'test' });
    expect(r.inputs.background.labelledLumenVoxels).toBe(shell.site.filter((s) => s === -1).length);
    expect(r.inputs.options.lumenLabel).toBe(4000);
    expect(r.cells.map((c) => c.label)).toEqual(shellLabels);
    expect(r.cells.map((c) => c.neighbours)).toEqual(shellResult.cells.map((c) => c.neighbours));
  });

  it('refuses, from the header alone, a volume whose voxels would not fit the memory allowed', () => {
    const bytes = tiffOf(shell, shellLabels, 16);
    const voxels = shell.width * shell.height * shell.depth;
    // 2 bytes a voxel of label, 2 of working arrays, and the file: one byte short is refused, the exact figure is not.
    const needed = bytes.length + voxels * 4;
    const options = (maxBytes: number) => ({ voxelSize: shell.voxel, version: 'test', memory: { maxBytes, why: 'allowed here' } });
    expect(() => measureVolume(input(bytes), options(needed - 1))).toThrow(
      new RegExp(
        `volume\\.tif: ${shell.width} x ${shell.height} x ${shell.depth} voxels of 16 bits need about .* MiB to measure, over the .* MiB allowed here; crop`,
      ),
    );
    expect(measureVolume(input(bytes), options(needed)).cells).toHaveLength(shellResult.cells.length);
  });

  it('ignores small enclosed pockets of background between cells (not a lumen)', () => {
    const data = labelData(shell, shellLabels, 16) as Uint16Array;
    // Three 2 x 2 x 1 holes inside cells, in the middle of the shell's wall.
    let holes = 0;
    for (let i = 0; i < data.length && holes < 3; i += 9973) {
      const neighbours = [i, i + 1, i + shell.width, i + shell.width + 1];
      const around = [i - 1, i + 2, i - shell.width, i + 2 * shell.width, i - shell.width * shell.height, i + shell.width * shell.height];
      if ([...neighbours, ...around].every((k) => shell.site[k] >= 0)) {
        for (const k of neighbours) data[k] = 0;
        holes++;
      }
    }
    expect(holes).toBe(3);
    const r = measureVolume(input(writeTiff(volumePages(shell, data, 16) as never)), { voxelSize: shell.voxel, version: 'test' });
    expect(r.inputs.background).toMatchObject({ lumenComponents: 1, pockets: 3, pocketVoxels: 12 });
    expect(r.cells.map((c) => c.neighbours)).toEqual(shellResult.cells.map((c) => c.neighbours));
  });

  it('refuses, or warns about, background lines between the cells', () => {
    expect(shellResult.warnings).toEqual([]);
    const data = labelData(shell, shellLabels, 16) as Uint16Array;
    const lined = data.slice();
    const { width: W, height: H } = shell;
    for (let i = 0; i < data.length; i++) {
      for (const j of [i + 1, i + W, i + W * H]) if (j < data.length && data[i] && data[j] && data[i] !== data[j]) lined[i] = 0;
    }
    // Lines all round: the lumen joins the outside through them.
    expect(() => measureVolume(input(writeTiff(volumePages(shell, lined, 16) as never)), { voxelSize: shell.voxel, version: 'test' })).toThrow(
      /no lumen: .*lines of 0 between cells/,
    );
    // Lines that stop short of the lumen: measured, with a warning.
    const plane = W * H;
    for (let i = 0; i < data.length; i++) {
      const [x, y, z] = [i % W, Math.floor(i / W) % H, Math.floor(i / plane)];
      const p = [
        (x + 0.5) * shell.voxel.x - (W * shell.voxel.x) / 2,
        (y + 0.5) * shell.voxel.y - (H * shell.voxel.y) / 2,
        (z + 0.5) * shell.voxel.z - (shell.depth * shell.voxel.z) / 2,
      ];
      // Keep the labels within 1.5 µm of the inner ellipsoid (the lumen side stays sealed).
      if (Math.hypot(p[0] / (SHELL.a + 1.5), p[1] / (SHELL.b + 1.5), p[2] / (SHELL.c + 1.5)) < 1) lined[i] = data[i];
    }
    const r = measureVolume(input(writeTiff(volumePages(shell, lined, 16) as never)), { voxelSize: shell.voxel, version: 'test' });
    expect(r.warnings.join('\n')).toMatch(/cells barely touch each other .*lines of 0 between cells/);
  });

  it('has the layers mode result shape: analyses[0] an AnalysisRecord over basal, apical', () => {
    const a = shellResult.analyses[0];
    expect(a.method).toBe('labels');
    expect(a.protocol).toBe('default');
    expect(a.summary.surfaces).toBe(2);
    expect(a.summary.perSurface.map((s) => s.label)).toEqual(['basal', 'apical']);
    expect(a.cells).toHaveLength(shell.sites);
    for (const cell of shellResult.cells) {
      const stats = a.cells[cell.id];
      expect(stats.sides).toEqual([cell.neighbours[0].length, cell.neighbours[1].length]);
      const union = new Set([...cell.neighbours[0], ...cell.neighbours[1]]);
      expect(stats.neighbours3D).toBe(union.size);
      expect(cell.won).toBe(cell.neighbours[1].filter((l) => !cell.neighbours[0].includes(l)).length);
      expect(cell.lost).toBe(cell.neighbours[0].filter((l) => !cell.neighbours[1].includes(l)).length);
    }
    expect(shellResult.kind).toBe('measured');
    expect(shellResult.exclusions).toEqual({ touchesFaces: 0, missing: 0, total: 0 });
    expect(shellResult.quartetFilter).toBeNull();
  });

  it('with the quartet filter keeps only exchanges confirmed by an intercalating quartet', () => {
    const r = measureVolume(input(tiffOf(shell, shellLabels, 16)), { voxelSize: shell.voxel, quartetFilter: true, version: 'test' });
    expect(r.inputs.options.quartetFilter).toBe(true);
    const q = r.quartetFilter!;
    expect(q).not.toBeNull();
    const confirmed = new Set<string>();
    for (const [a, b, c, d] of q.quartets) {
      const cell = (l: number) => r.cells.find((x) => x.label === l)!;
      // a-b on the basal surface only, c-d on the apical only, c and d touching a and b on both.
      expect(cell(a).neighbours[0]).toContain(b);
      expect(cell(a).neighbours[1]).not.toContain(b);
      expect(cell(c).neighbours[1]).toContain(d);
      expect(cell(c).neighbours[0]).not.toContain(d);
      for (const x of [c, d]) for (const y of [a, b]) for (const k of [0, 1]) expect(cell(y).neighbours[k]).toContain(x);
      confirmed.add(`${a}-${b}`).add(`${c}-${d}`);
    }
    // What remains exchanged is confirmed; scutoids only among quartet members.
    for (const cell of r.cells) {
      for (const l of cell.neighbours[0])
        if (!cell.neighbours[1].includes(l)) expect(confirmed.has(`${Math.min(cell.label, l)}-${Math.max(cell.label, l)}`)).toBe(true);
      if (cell.scutoid) expect(q.quartets.some((x) => x.includes(cell.label))).toBe(true);
    }
    expect(r.analyses[0].summary.scutoids).toBeLessThanOrEqual(shellResult.analyses[0].summary.scutoids);
  });
});

describe('measure --volume: an open tube cut by the volume (gland)', () => {
  it('finds its lumen reaching the faces, excludes the cells on the faces, and the exact neighbours of the others', () => {
    const labels = permutedLabels(tube.sites, 1, 1, 21);
    const r = measureVolume(input(tiffOf(tube, labels, 16)), { voxelSize: tube.voxel, version: 'test' });
    expect(r.inputs.background.lumenComponents).toBe(1);
    // Cells with a voxel in the first or last page are excluded (and only those: the tube stays inside x, y).
    const onFace = new Set<number>();
    const plane = tube.width * tube.height;
    for (let i = 0; i < plane; i++) {
      for (const s of [tube.site[i], tube.site[(tube.depth - 1) * plane + i]]) if (s >= 0) onFace.add(labels[s]);
    }
    for (const cell of r.cells) {
      expect(cell.valid).toBe(!onFace.has(cell.label));
      if (onFace.has(cell.label)) {
        expect(cell.scutoid).toBe(false);
        expect(cell.exclusion!.touchesFaces.some((f) => f === 'first page' || f === 'last page')).toBe(true);
        expect(cell.exclusion!.reason).toMatch(/touches the volume's .*page/);
      } else expect(cell.exclusion).toBeNull();
    }
    expect(r.exclusions.touchesFaces).toBe(onFace.size);
    expect(r.analyses[0].summary.validCells).toBe(tube.sites - onFace.size);
    expect(r.analyses[0].summary.validCells).toBeGreaterThan(15);
    const a = agreement(r, tube, labels, 1.1);
    expect(a.wrong).toEqual([]);
    expect(a.checked).toBeGreaterThan(200);
    // Apical twice... the outer surface is 1.8 times wider: cells exchange neighbours.
    expect(r.analyses[0].summary.percentScutoids).toBeGreaterThan(30);
    // Excluded cells still count as neighbours of valid ones.
    expect(r.cells.filter((c) => c.valid).some((c) => c.neighbours[0].some((l) => onFace.has(l)))).toBe(true);
  });

  it('does the same for a tube along x with voxels of three different sizes', () => {
    const spec = { width: 50, height: 60, depth: 40, voxel: { x: 1, y: 0.4, z: 0.6 }, inner: 6, outer: 11, sites: 30, seed: 6, axis: 'x' as const };
    const along = tubeVolume(spec);
    const labels = permutedLabels(along.sites, 1000, 37, 5);
    const r = measureVolume(input(tiffOf(along, labels, 16)), { voxelSize: along.voxel, minContact: 2, version: 'test' });
    const onFace = new Set<number>();
    for (let z = 0; z < along.depth; z++) {
      for (let y = 0; y < along.height; y++) {
        for (const x of [0, along.width - 1]) {
          const s = along.site[(z * along.height + y) * along.width + x];
          if (s >= 0) onFace.add(labels[s]);
        }
      }
    }
    for (const cell of r.cells) {
      expect(cell.valid).toBe(!onFace.has(cell.label));
      if (!cell.valid) expect(cell.exclusion!.touchesFaces.every((f) => f === 'first column' || f === 'last column')).toBe(true);
    }
    const a = agreement(r, along, labels, 1.1);
    expect(a.wrong).toEqual([]);
    expect(a.checked).toBeGreaterThan(150);
    const { comparison } = compareVolume(r, { realizations: 2, seed: 3, maxK: 3 });
    const g = comparison!.geometry;
    if (g.kind !== 'tube') throw new Error('expected the fitted tube');
    expect(Math.abs(g.axis[0])).toBeGreaterThan(0.995);
    expect(g.innerRadius).toBeCloseTo(spec.inner, 0);
    expect(g.outerRadius).toBeCloseTo(spec.outer, 0);
  });

  it('applies a 3 µm min-contact (6 voxels across) to the true lengths', () => {
    const labels = Array.from({ length: tube.sites }, (_, k) => k + 1);
    const r = measureVolume(input(tiffOf(tube, labels, 16)), { voxelSize: tube.voxel, minContact: 3, version: 'test' });
    const a = agreement(r, tube, labels, 1.1);
    expect(a.wrong).toEqual([]);
    expect(a.staircaseWrong).toBeGreaterThan(3);
  });
});

describe('measure --volume --compare: the model of the same tissue', () => {
  it('models an open tube by its fitted tube: axis, radii, length from the segmentation, Voronoi k, mean ± 95 % CI', () => {
    const labels = Array.from({ length: tube.sites }, (_, k) => k + 1);
    const r = measureVolume(input(tiffOf(tube, labels, 16)), { voxelSize: tube.voxel, version: 'test' });
    expect(r.inputs.background.lumenReachesFaces).toBe(true);
    const lines: string[] = [];
    const { comparison, note } = compareVolume(r, { realizations: 4, seed: 1, onProgress: (l) => lines.push(l) });
    expect(note).toBe('');
    const c = comparison!;
    const g = c.geometry;
    if (g.kind !== 'tube') throw new Error('expected the fitted tube');
    expect(Math.abs(g.axis[2])).toBeGreaterThan(0.999); // the tube runs along z
    expect(g.innerRadius).toBeCloseTo(TUBE.inner, 0);
    expect(g.outerRadius).toBeCloseTo(TUBE.outer, 0);
    expect(Math.abs(g.length / (TUBE.depth * TUBE.voxel.z) - 1)).toBeLessThan(0.05);
    expect(g.seededLayer).toBe('apical');
    expect(g.seededCells).toBe(tube.sites);
    expect(g.thickness.mean).toBeGreaterThan(0.8 * (TUBE.outer - TUBE.inner));
    expect(c.surfaceRatio).toBeCloseTo(g.outerRadius / g.innerRadius, 12);
    expect(c.candidates).toHaveLength(10);
    expect(c.bestK).toBe(c.candidates.reduce((a, b) => (b.distance < a.distance ? b : a)).k);
    expect(c.percentScutoids).toHaveLength(4);
    for (const key of ['percentScutoids', 'transitions', 'neighbours3D'] as const) {
      const { mean, ci95 } = c.model[key];
      expect(ci95[0]).toBeLessThanOrEqual(mean);
      expect(ci95[1]).toBeGreaterThanOrEqual(mean);
    }
    expect(c.model.percentScutoids.mean).toBeCloseTo(c.meanPercentScutoids, 12);
    expect(c.measured.percentScutoids).toBe(r.analyses[0].summary.percentScutoids);
    // The same construction (random sites, radial projection, ratio 1.8): the model agrees with the measurement.
    expect(Math.abs(c.model.percentScutoids.mean - c.measured.percentScutoids)).toBeLessThan(25);
    expect(lines.some((l) => l.startsWith('model Voronoi 10'))).toBe(true);
  });

  it('models a closed shell on its own surface meshes: Voronoi k on the lumen side, sites carried along the normal', () => {
    expect(shellResult.inputs.background.lumenReachesFaces).toBe(false);
    expect(compareVolume(shellResult, { realizations: 2, seed: 1 }).note).toMatch(/closed shell is modelled on its own surface meshes/);
    let meshes: Parameters<typeof compareVolume>[2];
    const r = measureVolume(input(tiffOf(shell, shellLabels, 16)), { voxelSize: shell.voxel, version: 'test', onSurfaceMeshes: (m) => (meshes = m) });
    expect(r.cells).toEqual(shellResult.cells); // the meshes change nothing measured
    const { comparison, note } = compareVolume(r, { realizations: 4, seed: 1 }, meshes);
    expect(note).toBe('');
    const c = comparison!;
    const g = c.geometry;
    if (g.kind !== 'mesh') throw new Error('expected the shell meshes');
    // The meshes are the tissue's surfaces: their areas are the exact ellipsoids' within 2 %.
    const sum = (a: Float64Array) => a.reduce((x, y) => x + y, 0);
    expect(Math.abs(g.seeded.area / sum(shell.exactAreas!.inner) - 1)).toBeLessThan(0.02);
    expect(Math.abs(g.other.area / sum(shell.exactAreas!.outer) - 1)).toBeLessThan(0.02);
    expect(g.seededLayer).toBe('apical');
    expect(g.seededCells).toBe(shell.sites);
    expect(g.projection).toEqual({ alongNormal: 4 * shell.sites, parallel: 0 });
    expect(g.thickness.mean).toBeCloseTo(SHELL.h, 0);
    expect(c.surfaceRatio).toBeCloseTo(g.other.area / g.seeded.area, 12);
    expect(c.candidates).toHaveLength(10);
    expect(c.bestK).toBe(c.candidates.reduce((a, b) => (b.distance < a.distance ? b : a)).k);
    expect(c.percentScutoids).toHaveLength(4);
    for (const key of ['percentScutoids', 'transitions', 'neighbours3D'] as const) {
      const { mean, ci95 } = c.model[key];
      expect(ci95[0]).toBeLessThanOrEqual(mean);
      expect(ci95[1]).toBeGreaterThanOrEqual(mean);
    }
    // The model of the same shell and thickness gives scutoids in the measured range.
    expect(Math.abs(c.model.percentScutoids.mean - c.measured.percentScutoids)).toBeLessThan(25);
    expect(c.model.neighbours3D.mean).toBeGreaterThan(5.5);
  });

  it('fits circles, axes and confidence intervals exactly on exact data', () => {
    const points = Array.from({ length: 12 }, (_, k): [number, number] => [3 + 5 * Math.cos(k), -2 + 5 * Math.sin(k)]);
    const c = fitCircle(points);
    expect([c.cx, c.cy, c.r].map((x) => +x.toFixed(9))).toEqual([3, -2, 5]);
    const e = smallestEigenvector([
      [2, 0, 0],
      [0, 3, 0],
      [0, 0, 0.5],
    ]);
    expect(Math.abs(e[2])).toBeCloseTo(1, 12);
    const i = interval([1, 2, 3, 4]);
    expect(i.mean).toBe(2.5);
    expect(i.ci95[1] - i.mean).toBeCloseTo((3.182 * Math.sqrt(5 / 3)) / 2, 9);
    // A percentage's interval stays within 0..100 (realizations of 0 and 100 % would reach past both).
    const p = interval([0, 100, 100], 100);
    expect(p.ci95[0]).toBe(0);
    expect(p.ci95[1]).toBe(100);
    expect(interval([5, 6, 40], 100).ci95[0]).toBe(0);
  });
});
