/**
 * The seeded surfaces a SheetRunner keeps, newest last, by key (engine, centroid path and the
 * config without `sheet`). One is the classic case (a slider over `sheet.*`); a page's worker
 * keeps a few, so the realizations of a headline (seeds seed + 1, ...) each keep their converged
 * surface and a later ratio or thickness change recomputes only their stacks (issue 27).
 * Bounded by count and by the bytes of the label images and sites held, the newest always kept.
 */
import type { SeededSurface } from './relax';

type Seeded = SeededSurface<unknown, unknown>;

/**
 * Seeded surfaces a page's pipeline runner keeps: the realizations of a headline (default 5)
 * each keep theirs, so a ratio or thickness change recomputes only their stacks.
 */
export const WORKER_KEEP_SEEDED = 8;

/** Past this many bytes of label images and sites, older seeded surfaces are dropped. */
const MAX_KEPT_BYTES = 64 * 1024 * 1024;

export class SeededCache {
  private readonly entries = new Map<string, { seeded: Promise<Seeded>; bytes: number }>();

  constructor(private readonly keep: number) {}

  /** The seeded surface kept under `key` (now the newest), or a new one from `make`. */
  get(key: string, make: () => Promise<Seeded>): Promise<Seeded> {
    const known = this.entries.get(key);
    if (known) {
      this.entries.delete(key);
      this.entries.set(key, known);
      return known.seeded;
    }
    const entry = { seeded: make(), bytes: 0 };
    this.entries.set(key, entry);
    entry.seeded.then(
      (seeded) => {
        entry.bytes = (seeded.labels?.byteLength ?? 0) + byteLength(seeded.sites);
        this.trim();
      },
      () => this.entries.get(key) === entry && this.entries.delete(key),
    );
    this.trim();
    return entry.seeded;
  }

  /** Forgets `key` (a failed or cancelled surface is not reused). */
  drop(key: string, seeded: Promise<Seeded>): void {
    if (this.entries.get(key)?.seeded === seeded) this.entries.delete(key);
  }

  private trim(): void {
    let bytes = 0;
    for (const entry of this.entries.values()) bytes += entry.bytes;
    for (const [key, entry] of this.entries) {
      if (this.entries.size <= 1 || (this.entries.size <= this.keep && bytes <= MAX_KEPT_BYTES)) break;
      this.entries.delete(key);
      bytes -= entry.bytes;
    }
  }
}

function byteLength(sites: unknown): number {
  return ArrayBuffer.isView(sites) ? sites.byteLength : 0;
}
