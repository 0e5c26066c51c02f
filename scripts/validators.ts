/**
 * Precompiled validators (scripts/validatorsCode.ts). `tsx scripts/validators.ts write` writes
 * them; `tsx scripts/validators.ts check` regenerates them in memory and exits 1, naming the
 * file, when the written one differs (CI runs it through `npm test`). The modules are generated,
 * not committed (.gitignore): `npm ci` / `npm install` write them in their `prepare` step.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { renderValidators } from './validatorsCode';

const root = fileURLToPath(new URL('..', import.meta.url));
const mode = process.argv[2];
const files = renderValidators();
if (mode === 'write') {
  for (const file of files) {
    writeFileSync(`${root}${file.path}`, file.text);
    console.log(`validators: wrote ${file.path}`);
  }
} else if (mode === 'check') {
  let stale = 0;
  for (const file of files) {
    let written = '';
    try {
      written = readFileSync(`${root}${file.path}`, 'utf8');
    } catch {
      // reported below as differing
    }
    if (written !== file.text) {
      console.error(`validators: ${file.path} differs from its schema; run npm run validators:write (npm install and npm ci run it as the prepare step)`);
      stale++;
    }
  }
  if (stale > 0) process.exit(1);
  console.log(`validators: ${files.map((f) => f.path).join(', ')} match their schemas`);
} else {
  console.error('usage: tsx scripts/validators.ts write|check');
  process.exit(2);
}
