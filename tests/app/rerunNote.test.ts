import { describe, expect, it } from 'vitest';
import { rerunNote } from '../../src/app/model/project';
import type { SheetResult } from '../../src/run';

/**
 * Opening a closed-surface result JSON runs its configuration again; the status line compares
 * the file with that run only. A run that did not finish (refused over budget, waiting for the
 * user's approval of a foreign mesh, cancelled, failed) is said as such, never compared with the
 * result that was on screen before.
 */
const resultAt = (positions: [number, number, number][]) => ({ cells: positions.map((position, id) => ({ id, position })) }) as unknown as SheetResult;

const file = resultAt([
  [10, 0, 0],
  [0, 10, 0],
]);
const other = resultAt([
  [88.1, 0, 0],
  [0, 10, 0],
]);

describe('rerunNote', () => {
  it('compares the file with the finished run of its configuration', () => {
    expect(rerunNote(file, { kind: 'done', result: file })).toMatch(/was run again; it reproduced the file's sites/);
    expect(rerunNote(file, { kind: 'done', result: other })).toMatch(/was run again; its sites differ from the file's by up to 78\.1 µm/);
  });

  it('says what happened when nothing ran, and compares nothing', () => {
    const notes = {
      refused: rerunNote(file, { kind: 'refused', message: 'over budget' }),
      waiting: rerunNote(file, { kind: 'waiting', path: '/organoid.ply', host: 'lab.example' }),
      cancelled: rerunNote(file, { kind: 'cancelled' }),
      failed: rerunNote(file, { kind: 'failed', message: 'boom' }),
    };
    expect(notes.refused).toMatch(/the run was refused .*nothing was run and the previous result is still shown/);
    expect(notes.waiting).toMatch(/will be run again once you allow loading \/organoid\.ply from lab\.example/);
    expect(notes.cancelled).toMatch(/the run was cancelled; the previous result is still shown/);
    expect(notes.failed).toMatch(/the run failed/);
    for (const note of Object.values(notes)) {
      expect(note).not.toMatch(/differ|reproduced|was run again;/);
    }
  });
});
