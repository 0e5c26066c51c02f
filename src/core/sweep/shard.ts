/**
 * Splitting a sweep across machines, deterministically, and putting it back together.
 *
 * - Order: `orderForReuse` puts the runs that share a seeded surface (the same config but for
 *   `sheet.*`, and the same seed) next to each other, groups in order of first appearance and
 *   runs in grid order inside a group, so a runner that keeps its last seeded surface relaxes
 *   each one once (a sweep over surface ratios relaxes each realization once, not once per
 *   ratio). Both the sweep and `merge` write rows in this order, so a merged runs.csv is the
 *   unsharded one.
 * - Shards: `shardRuns` deals these groups round-robin: group g (0-based, in that order) goes to
 *   shard g mod N. Every run is in exactly one shard, every shard gets the same number of groups
 *   give or take one, and groups of every Voronoi k reach every shard (groups are ordered by the
 *   grid, so consecutive groups differ in realization or Voronoi k). Dealing single runs instead
 *   (every N-th run) would split each group across shards and relax each seeded surface N times.
 *   When no `sheet.*` field varies every group is one run and the shard is every N-th run.
 * - `parseShard`: "I/N" (1 <= I <= N, the I-th of N shards) or "slurm" (from the array job's
 *   SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT: task MIN is shard 1).
 */
import type { ConfigObject, SweepRun } from './expand';
import { SweepSpecError } from './spec';

export interface Shard {
  /** 1-based: 1..count. */
  readonly index: number;
  readonly count: number;
}

const MAX_SHARDS = 1_000_000;

/** The shard named by `--shard TEXT` (environment for "slurm"); errors name --shard or the variable. */
export function parseShard(text: string, env: Record<string, string | undefined> = {}): Shard {
  if (text === 'slurm') return slurmShard(env);
  const match = /^(\d+)\/(\d+)$/.exec(text.trim());
  if (!match) throw new SweepSpecError('--shard', `--shard: ${JSON.stringify(text)} is not I/N (e.g. 2/4, the second of four shards) or "slurm"`);
  const index = Number(match[1]);
  const count = Number(match[2]);
  if (!(count >= 1 && count <= MAX_SHARDS)) throw new SweepSpecError('--shard', `--shard: the number of shards N must be 1 to ${MAX_SHARDS} (got ${match[2]})`);
  if (!(index >= 1 && index <= count))
    throw new SweepSpecError('--shard', `--shard: I must be 1 to ${count} in I/N (got ${match[1]}; shards are numbered from 1)`);
  return { index, count };
}

function slurmShard(env: Record<string, string | undefined>): Shard {
  const read = (name: string): number => {
    const value = env[name];
    if (value === undefined || value === '') {
      throw new SweepSpecError('--shard', `--shard slurm: ${name} is not set; run inside an array job (sbatch --array=1-N), or give --shard I/N`);
    }
    const n = Number(value);
    if (!Number.isInteger(n) || n < 0) throw new SweepSpecError('--shard', `--shard slurm: ${name}=${JSON.stringify(value)} is not a non-negative integer`);
    return n;
  };
  const id = read('SLURM_ARRAY_TASK_ID');
  const min = read('SLURM_ARRAY_TASK_MIN');
  const count = read('SLURM_ARRAY_TASK_COUNT');
  const index = id - min + 1;
  if (count < 1 || count > MAX_SHARDS) throw new SweepSpecError('--shard', `--shard slurm: SLURM_ARRAY_TASK_COUNT=${count} must be 1 to ${MAX_SHARDS}`);
  if (index < 1 || index > count) {
    throw new SweepSpecError(
      '--shard',
      `--shard slurm: task ${id} is not one of ${count} consecutive tasks from ${min} (SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN must be below SLURM_ARRAY_TASK_COUNT); use --array=A-B without a step or %, or give --shard I/N`,
    );
  }
  return { index, count };
}

/** Runs grouped by `groupKey` (groups in order of first appearance, grid order inside). */
export function orderForReuse<C extends ConfigObject>(runs: readonly SweepRun<C>[], groupKey: (run: SweepRun<C>) => string): SweepRun<C>[] {
  const groups = new Map<string, SweepRun<C>[]>();
  for (const run of runs) {
    const key = groupKey(run);
    let group = groups.get(key);
    if (!group) groups.set(key, (group = []));
    group.push(run);
  }
  return [...groups.values()].flat();
}

/** The runs of one shard, in reuse order (see the module comment). */
export function shardRuns<C extends ConfigObject>(runs: readonly SweepRun<C>[], shard: Shard, groupKey: (run: SweepRun<C>) => string): SweepRun<C>[] {
  const groupIndex = new Map<string, number>();
  const mine: SweepRun<C>[] = [];
  for (const run of orderForReuse(runs, groupKey)) {
    const key = groupKey(run);
    let g = groupIndex.get(key);
    if (g === undefined) groupIndex.set(key, (g = groupIndex.size));
    if (g % shard.count === shard.index - 1) mine.push(run);
  }
  return mine;
}

/** Rows sorted by their run's position in `order` (rows of unknown keys last, in input order). */
export function sortRowsByRuns<C extends ConfigObject>(rows: readonly Record<string, string>[], order: readonly SweepRun<C>[]): Record<string, string>[] {
  const position = new Map(order.map((run, k) => [run.key, k]));
  return rows
    .map((row, k) => ({ row, at: position.get(row.key) ?? order.length + k }))
    .sort((a, b) => a.at - b.at)
    .map(({ row }) => row);
}
