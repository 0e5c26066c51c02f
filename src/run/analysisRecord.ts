import type { ScutoidAnalysis } from '../core/analysis';
import type { AnalysisRecord } from './result';

/** The JSON form of a scutoid analysis: per-cell records instead of typed arrays. */
export function analysisRecord(method: 'labels' | 'exact', minContactLength: number, analysis: ScutoidAnalysis): AnalysisRecord {
  const c = analysis.cells;
  const cells = Array.from(c.valid, (valid, id) => ({
    id,
    valid: valid === 1,
    scutoid: c.scutoid[id] === 1,
    won: c.won[id],
    lost: c.lost[id],
    transitions: c.transitions[id],
    neighbours3D: c.neighbours3D[id],
    sides: c.sides.map((perSurface) => perSurface[id]),
  }));
  return { method, minContactLength, summary: analysis.summary, cells };
}
