/** Baseline for bench/measureVolume.ts: reads and decodes a label volume, nothing else. */
import { readFileSync } from 'node:fs';
import { decodeVolumeTiff, inspectVolumeTiff } from '../src/core/measure';

const file = process.argv[2];
const t0 = performance.now();
const bytes = new Uint8Array(readFileSync(file));
const volume = decodeVolumeTiff(bytes, file, inspectVolumeTiff(bytes, file));
process.stderr.write(`decoded ${volume.width} x ${volume.height} x ${volume.depth} in ${(performance.now() - t0).toFixed(0)} ms\n`);
