/**
 * Collects the contacts a restricted Voronoi computation finds, cell by cell, and turns them
 * into the symmetric rows of the adjacency record (src/core/analysis/adjacency.ts).
 *
 * Each cell's computation sees its own side of a contact: cell i measures the part of the
 * bisector (i, j) on its boundary, cell j measures the same curve from its side. In exact
 * arithmetic both are equal; in floating point they agree to rounding, and a contact through
 * a Voronoi vertex of four cells may be seen by one side only with a length at rounding level.
 * `finish` therefore keeps a pair when either side measured more than `tolerance` µm and
 * reports the mean of the two sides (or the one side that saw it), so the result is
 * symmetric by construction.
 *
 * Records go into growable typed arrays (amortised doubling, no per-contact objects).
 */
import type { SurfaceAdjacency } from '../analysis/adjacency';

export class ContactRecorder {
  private from = new Int32Array(1024);
  private to = new Int32Array(1024);
  private length = new Float64Array(1024);
  private size = 0;
  /** Per-cell scratch: summed length towards each other cell during one cell's pass. */
  private readonly pending: Float64Array;
  private readonly touched: Int32Array;
  private touchedCount = 0;
  private current = -1;

  constructor(readonly count: number) {
    this.pending = new Float64Array(count);
    this.touched = new Int32Array(count);
  }

  /** Starts (or resumes) accumulating the contacts of cell i. */
  begin(i: number): void {
    this.flush();
    this.current = i;
  }

  /** Adds `len` µm of boundary between the current cell and cell j. */
  add(j: number, len: number): void {
    if (!(len > 0)) return;
    if (this.pending[j] === 0) this.touched[this.touchedCount++] = j;
    this.pending[j] += len;
  }

  /** Writes the current cell's pending contacts as records. */
  flush(): void {
    const i = this.current;
    for (let t = 0; t < this.touchedCount; t++) {
      const j = this.touched[t];
      if (this.size === this.from.length) this.grow();
      this.from[this.size] = i;
      this.to[this.size] = j;
      this.length[this.size++] = this.pending[j];
      this.pending[j] = 0;
    }
    this.touchedCount = 0;
    this.current = -1;
  }

  private grow(): void {
    const n = 2 * this.from.length;
    const f = new Int32Array(n),
      t = new Int32Array(n),
      l = new Float64Array(n);
    f.set(this.from);
    t.set(this.to);
    l.set(this.length);
    this.from = f;
    this.to = t;
    this.length = l;
  }

  /**
   * The symmetric adjacency: neighbours sorted per cell, a pair kept when either side saw
   * more than `tolerance` µm, length = mean of the sides that saw it.
   */
  finish(tolerance: number): Pick<SurfaceAdjacency, 'offsets' | 'neighbours' | 'lengths'> {
    this.flush();
    const n = this.count,
      size = this.size;
    // Directed records grouped by cell (counting sort), then summed per (i, j) after sorting
    // each cell's run by j (a cell can be visited by more than one traversal).
    const start = new Int32Array(n + 1);
    for (let r = 0; r < size; r++) start[this.from[r] + 1]++;
    for (let i = 0; i < n; i++) start[i + 1] += start[i];
    const cursor = start.slice(0, n);
    const ids = new Int32Array(size);
    const lens = new Float64Array(size);
    for (let r = 0; r < size; r++) {
      const c = cursor[this.from[r]]++;
      ids[c] = this.to[r];
      lens[c] = this.length[r];
    }
    const perm = new Int32Array(size);
    const dirOffsets = new Int32Array(n + 1);
    const dirIds = new Int32Array(size);
    const dirLens = new Float64Array(size);
    let m = 0;
    for (let i = 0; i < n; i++) {
      const a = start[i],
        b = start[i + 1];
      for (let q = a; q < b; q++) perm[q] = q;
      perm.subarray(a, b).sort((x, y) => ids[x] - ids[y]);
      for (let q = a; q < b; q++) {
        const j = ids[perm[q]];
        if (j === i) continue;
        if (m > dirOffsets[i] && dirIds[m - 1] === j) dirLens[m - 1] += lens[perm[q]];
        else {
          dirIds[m] = j;
          dirLens[m++] = lens[perm[q]];
        }
      }
      dirOffsets[i + 1] = m;
    }
    // Union of both directions: count, then fill (sorted, since both runs are sorted by j).
    const offsets = new Int32Array(n + 1);
    const outIds: number[] = [];
    const outLens: number[] = [];
    const reverse = this.reverseRecords(n, dirOffsets, dirIds, dirLens);
    for (let i = 0; i < n; i++) {
      // Merge i's own run with the cells that listed i (reverse run, sorted by j).
      let p = dirOffsets[i],
        q = reverse.offsets[i];
      const pe = dirOffsets[i + 1],
        qe = reverse.offsets[i + 1];
      while (p < pe || q < qe) {
        const jp = p < pe ? dirIds[p] : Infinity;
        const jq = q < qe ? reverse.ids[q] : Infinity;
        const j = Math.min(jp, jq);
        const own = jp === j ? dirLens[p++] : 0;
        const other = jq === j ? reverse.lens[q++] : 0;
        const keep = own > tolerance || other > tolerance;
        if (!keep) continue;
        outIds.push(j);
        outLens.push(own > tolerance && other > tolerance ? 0.5 * (own + other) : Math.max(own, other));
      }
      offsets[i + 1] = outIds.length;
    }
    return { offsets, neighbours: Int32Array.from(outIds), lengths: Float64Array.from(outLens) };
  }

  /** For each cell j, the cells i that recorded a contact with j and its length, sorted by i. */
  private reverseRecords(n: number, off: Int32Array, ids: Int32Array, lens: Float64Array) {
    const offsets = new Int32Array(n + 1);
    for (let q = 0; q < off[n]; q++) offsets[ids[q] + 1]++;
    for (let j = 0; j < n; j++) offsets[j + 1] += offsets[j];
    const cursor = offsets.slice(0, n);
    const rid = new Int32Array(off[n]);
    const rlen = new Float64Array(off[n]);
    // i ascending, so each j's run comes out sorted by i.
    for (let i = 0; i < n; i++) {
      for (let q = off[i]; q < off[i + 1]; q++) {
        const c = cursor[ids[q]]++;
        rid[c] = i;
        rlen[c] = lens[q];
      }
    }
    return { offsets, ids: rid, lens: rlen };
  }
}
