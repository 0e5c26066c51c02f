/** Runs the CLI from source (for timing and memory checks): node --import tsx tests/measure/runMeasure.ts measure ... */
import { main } from '../../src/cli/main';
process.exitCode = await main(process.argv.slice(2));
