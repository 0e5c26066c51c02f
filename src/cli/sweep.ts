import { appendFileSync, existsSync, mkdirSync, readFileSync, truncateSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateAnyConfig, type AnyConfig } from '../core/config';
import { aggregateRows, aggregateToCsv, aggregateToJson, expandSweep, runSweep, variedFields, type SweepSpec } from '../core/sweep';
import { createHeadlessContext } from '../node/headless';
import { SheetRunner, seededKey, sweepSummary } from '../run';
import { version } from '../version';

/**
 * `tissue-sheet sweep SWEEP.json --out DIR`: a grid of configurations x realizations.
 * SWEEP.json = { "base": config, "vary": { "dotted.path": [values] }, "realizations": n,
 * "seed": s, "seedMode": "per-realization" | "per-run" }. Writes DIR/runs.csv (one row per run,
 * appended as runs finish: rerunning the same command resumes), DIR/aggregate.csv and
 * DIR/aggregate.json (mean and SD per grid point) and DIR/sweep.json (the spec and version).
 */
export async function sweepCommand(specPath: string, outDir: string, log: (line: string) => void): Promise<void> {
  const spec = readSpec(specPath);
  // Validate every configuration before computing anything: a typo fails in a second, not an
  // hour. Then order runs so those sharing a seeded surface (same config but for `sheet`) are
  // consecutive: the runner relaxes it once and reuses it for every ratio or thickness.
  const keyed = expandSweep(spec).map((run) => {
    try {
      return { run, key: seededKey(validateAnyConfig(run.config)) };
    } catch (error) {
      throw new Error(`${specPath}: run ${run.key}: ${(error as Error).message}`);
    }
  });
  const firstIndex = new Map<string, number>();
  keyed.forEach(({ key }, index) => firstIndex.has(key) || firstIndex.set(key, index));
  const runs = keyed
    .sort((a, b) => firstIndex.get(a.key)! - firstIndex.get(b.key)! || a.run.index - b.run.index)
    .map(({ run }) => run);
  const fields = variedFields(spec);
  mkdirSync(outDir, { recursive: true });
  writeFileSync(join(outDir, 'sweep.json'), JSON.stringify({ software: { name: 'tissue-sheet', version }, spec }, null, 2) + '\n');
  const csvPath = join(outDir, 'runs.csv');
  const existingCsv = existsSync(csvPath) ? readFileSync(csvPath, 'utf8') : undefined;

  const context = createHeadlessContext();
  const runner = new SheetRunner(context);
  try {
    const result = await runSweep({
      runs,
      fields,
      existingCsv,
      append: (text) => appendFileSync(csvPath, text),
      truncate: (length) => truncateSync(csvPath, Buffer.byteLength(existingCsv!.slice(0, length))),
      runner: async (config) => sweepSummary((await runner.run(validateAnyConfig(config))).result),
      onProgress: (p) => {
        if (p.phase === 'start') return;
        const eta = p.finished > 0 ? ((p.elapsedMs / p.finished) * (p.total - p.finished)) / 1000 : 0;
        log(`${p.phase === 'done' ? 'done' : 'FAILED'} ${p.finished}/${p.total} ${p.run.key}  (${p.skipped} resumed, ~${eta.toFixed(0)} s left)`);
      },
    });
    const aggregate = aggregateRows(result.rows, fields);
    writeFileSync(join(outDir, 'aggregate.csv'), aggregateToCsv(aggregate));
    writeFileSync(join(outDir, 'aggregate.json'), JSON.stringify(aggregateToJson(aggregate), null, 2) + '\n');
    log(`sweep: ${result.completed} runs computed, ${result.skipped} resumed -> ${outDir}`);
  } finally {
    context.dispose();
  }
}

function readSpec(path: string): SweepSpec<AnyConfig & Record<string, unknown>> {
  let spec: unknown;
  try {
    spec = JSON.parse(readFileSync(path, 'utf8'));
  } catch (error) {
    throw new Error(`${path}: cannot read the sweep spec (${(error as Error).message})`);
  }
  if (typeof spec !== 'object' || spec === null || typeof (spec as { base?: unknown }).base !== 'object') {
    throw new Error(`${path}: a sweep spec needs "base" (a config object), and usually "vary" and "realizations"`);
  }
  const allowed = ['base', 'vary', 'realizations', 'seed', 'seedMode'];
  for (const key of Object.keys(spec)) {
    if (!allowed.includes(key)) throw new Error(`${path}: ${key}: unknown field; allowed: ${allowed.join(', ')}`);
  }
  // Same seed for every grid point of a realization: ratios are compared on the same sites,
  // and the converged seeded surface is computed once per realization.
  return { seedMode: 'per-realization', ...(spec as SweepSpec<AnyConfig & Record<string, unknown>>) };
}
