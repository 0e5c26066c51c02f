import { describe, expect, it } from 'vitest';
import { cellInfoLines, hoverText } from '../../src/app/view/cellInfo';
import type { ViewStack } from '../../src/view/stack';

/**
 * A closed-surface stack of 3 cells: on the seeded surface cell 0 touches 1, on the other it
 * touches 1 and 2 (the label images' neighbours), and an analysis of `method` whose own counts
 * for cell 0 are 2 won, 1 lost (another method can count otherwise). Only what the panel reads.
 */
function closedStack(method: 'exact' | 'labels' | null): ViewStack {
  const surface = (name: string, neighbours: number[][]) => ({
    name,
    sides: Int32Array.from(neighbours.map((n) => n.length + 4)),
    cells: neighbours.map((ids) => ({ neighbours: ids.map((id) => ({ id })) })),
  });
  return {
    closed: true,
    result: { cells: [{}, {}, {}] },
    analysis: method ? { method, cells: [{ won: 2, lost: 1, transitions: 3, neighbours3D: 4 }] } : null,
    surfaces: [surface('basal', [[1], [0], []]), surface('apical', [[1, 2], [0], [0]])],
    valid: Uint8Array.from([1, 1, 0]),
    scutoid: Uint8Array.from([1, 0, 0]),
  } as unknown as ViewStack;
}

describe('the cell panel names the method of every number (issue 26)', () => {
  it('exact flags beside label neighbours: each line says which method, and that they differ', () => {
    const lines = cellInfoLines(closedStack('exact'), 0);
    expect(lines[0]).toBe('Cell 0: valid, scutoid (exact method).');
    expect(lines[1]).toBe('Sides (exact method): basal 5, apical 6.');
    // The ids are the label images' neighbour sets' difference: cell 2 won, none lost.
    expect(lines[2]).toBe('Neighbours won from basal to apical: cell #2; lost: none (labels method).');
    expect(lines[3]).toMatch(/^These neighbour ids are the labels method's; the flags and sides above are the exact method's/);
    expect(lines[4]).toBe('Analysis (exact method): 2 won, 1 lost, 3 transitions, 4 3D neighbours.');
    expect(hoverText(closedStack('exact'), { surface: 1, cell: 0 })).toBe('Cell 0 (on apical) · sides basal 5, apical 6 · scutoid (exact method)');
  });

  it('one method throughout: no warning line; without an analysis the flags say where they come from', () => {
    const same = cellInfoLines(closedStack('labels'), 0);
    expect(same.some((line) => line.startsWith('These neighbour ids'))).toBe(false);
    expect(same.every((line) => /\((labels method|labels)\)|labels method/.test(line))).toBe(true);
    const none = cellInfoLines(closedStack(null), 2);
    expect(none[0]).toBe('Cell 2: border cell (not counted), not a scutoid (labels neighbours, no analysis).');
    expect(none).toHaveLength(3);
  });
});
