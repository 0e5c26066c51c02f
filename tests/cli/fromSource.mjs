// Runs the CLI from its TypeScript sources (tsx), so tests check the code as it is, without
// `npm run build:lib` first. Same entry as bin/tissue-sheet.mjs: main(argv) -> exit code.
// Needs an X display (tests run under xvfb-run -a).
import { register } from 'tsx/esm/api';

register();
const { main } = await import('../../src/cli/main.ts');
process.exitCode = await main(process.argv.slice(2));
