// Adds the file extension to every relative import in the emitted type declarations
// (`'./run/index'` -> `'./run/index.js'`), which TypeScript consumers with
// `"moduleResolution": "node16"/"nodenext"` need in an ES-module package; bundler resolution
// accepts either. Usage: node scripts/dts-extensions.mjs dist/types
import { existsSync, readdirSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';

const root = resolve(process.argv[2] ?? 'dist/types');
// from '...', import('...'), and bare `import '...'`, relative specifiers only.
const specifier = /(\bfrom\s*|\bimport\s*\(\s*|\bimport\s+)(['"])(\.{1,2}\/[^'"]*)\2/g;

function withExtension(file, spec) {
  if (/\.(js|mjs|cjs|json)$/.test(spec)) return spec;
  const base = resolve(dirname(file), spec);
  if (existsSync(base + '.d.ts')) return spec + '.js';
  if (existsSync(join(base, 'index.d.ts'))) return spec + '/index.js';
  // tsc resolved every real import, so this is text in a comment: leave it as written.
  console.warn(`dts-extensions: ${file}: no declaration for "${spec}", left as is`);
  return spec;
}

let files = 0;
for (const file of walk(root)) {
  const text = readFileSync(file, 'utf8');
  const fixed = text.replace(specifier, (_m, head, quote, spec) => `${head}${quote}${withExtension(file, spec)}${quote}`);
  if (fixed !== text) {
    writeFileSync(file, fixed);
    files++;
  }
}
console.log(`dts-extensions: ${files} declaration files in ${root} now import with extensions`);

function* walk(dir) {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) yield* walk(path);
    else if (name.endsWith('.d.ts')) yield path;
  }
}
