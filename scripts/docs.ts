/**
 * Generated docs. `tsx scripts/docs.ts write` writes docs/config.md from the config schema and
 * its template; `tsx scripts/docs.ts check` regenerates it in memory and exits 1, naming the
 * first differing line, when the committed page differs (CI runs it through `npm test`).
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { CONFIG_DOCS_PATH, CONFIG_TEMPLATE_PATH, checkConfigDocs, renderConfigDocs } from './docsConfig';

const root = fileURLToPath(new URL('..', import.meta.url));
const read = (path: string) => readFileSync(`${root}${path}`, 'utf8');

const mode = process.argv[2];
const generated = renderConfigDocs(read(CONFIG_TEMPLATE_PATH));
if (mode === 'write') {
  writeFileSync(`${root}${CONFIG_DOCS_PATH}`, generated);
  console.log(`docs: wrote ${CONFIG_DOCS_PATH}`);
} else if (mode === 'check') {
  let committed: string;
  try {
    committed = read(CONFIG_DOCS_PATH);
  } catch {
    console.error(`docs: ${CONFIG_DOCS_PATH} cannot be read; run npm run docs:write and commit it`);
    process.exit(1);
  }
  const problem = checkConfigDocs(committed, generated);
  if (problem) {
    console.error(`docs: ${problem}`);
    process.exit(1);
  }
  console.log(`docs: ${CONFIG_DOCS_PATH} matches the schema`);
} else {
  console.error('usage: tsx scripts/docs.ts write|check');
  process.exit(2);
}
