#!/usr/bin/env bash
# Checks the npm package as a consumer gets it (README, "Use it as a package"): `npm pack`, then
# in an empty project whose package.json allows gl's install script, `npm install <tarball>`:
#   - no dev dependency came along (tsx, vite, ...), and the packed code imports every runtime
#     dependency;
#   - `import('tissue-sheet')` and `import('tissue-sheet/node')` work in Node, and the main
#     entry (and `tissue-sheet/element`) statically import no Node built-in or gl;
#   - a consumer's TypeScript typechecks against the declarations ("moduleResolution": "nodenext");
#   - `npx tissue-sheet run` computes a small sheet;
#   - with gl's native module hidden, then gl itself hidden, the CLI exits 3 with one line
#     saying what to run (a consumer who denied or omitted gl).
# Needs the registry (the package's dependencies) and what headless-gl needs to build and run
# (python3, make, g++, xvfb-run; scripts/test-all.sh installs the system packages).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tissue-sheet-pack-XXXXXX")
trap 'rm -rf "$work"' EXIT
started=$SECONDS
step() { echo "== $* ($((SECONDS - started)) s)"; }
fail() { echo "check-pack: FAILED: $*" >&2; exit 1; }

step "npm pack (prepack builds dist/)"
npm pack --silent --pack-destination "$work" > "$work/pack.out" 2> "$work/pack.log" ||
  { cat "$work/pack.out" "$work/pack.log" | grep -v '^npm warn' | tail -n 20 || true; fail "npm pack (its prepack build, npm run build:lib) failed"; }
tarball=$(tail -n 1 "$work/pack.out")
[ -f "$work/$tarball" ] || fail "npm pack wrote no tarball"
echo "$tarball: $(du -k "$work/$tarball" | cut -f1) KiB packed, $(tar -tzf "$work/$tarball" | wc -l) files"
if tar -tzf "$work/$tarball" | grep -E '^package/(src|tests|e2e|bench|node_modules|dist/app)/'; then
  fail "the tarball ships sources, tests or the app (listed above); fix \"files\" in package.json"
fi
# Assets the modules load by URL (the pipeline worker) must be in the tarball too.
packed=$(tar -tzf "$work/$tarball")
for asset in $(tar -xzOf "$work/$tarball" --wildcards 'package/dist/*.js' | grep -o 'assets/[A-Za-z0-9_.-]*\.js' | sort -u); do
  printf '%s\n' "$packed" | grep -q "/$asset\$" || fail "a packed module loads $asset, which is not packed"
done

consumer="$work/consumer"
mkdir "$consumer"
cd "$consumer"
echo '{ "name": "consumer", "private": true, "type": "module", "allowScripts": { "gl": true } }' > package.json

step "npm install the tarball (builds headless-gl)"
npm install --no-audit --no-fund --loglevel=error "$work/$tarball"
for dev in tsx vite vitest typescript @playwright/test uplot lil-gui; do
  [ ! -e "node_modules/$dev" ] || fail "node_modules/$dev is installed: a dev-only package is a runtime dependency"
done
echo "installed: $(ls node_modules | wc -l) packages, $(du -sh node_modules | cut -f1)"

step "import the library in Node"
node -e "import('tissue-sheet').then((m) => { console.log('tissue-sheet: runSheet', typeof m.runSheet, '| validateConfig', typeof m.validateConfig, '| runSweep', typeof m.runSweep); if (typeof m.runSheet !== 'function') process.exit(1); })"
node -e "import('tissue-sheet/node').then((m) => { console.log('tissue-sheet/node: createHeadlessContext', typeof m.createHeadlessContext); if (typeof m.createHeadlessContext !== 'function') process.exit(1); })"

step "the main entry is browser-safe: no Node built-in or gl in its static imports"
cat > browser-safe.cjs <<'EOF'
const fs = require('fs'), path = require('path');
const root = path.resolve('node_modules/tissue-sheet/dist/esm'), seen = new Set(), bad = [];
const visit = (file) => {
  if (seen.has(file)) return;
  seen.add(file);
  for (const [, spec] of fs.readFileSync(file, 'utf8').matchAll(/^(?:import|export)\s[^'";]*['"]([^'"]+)['"]/gm)) {
    if (spec.startsWith('.')) visit(path.resolve(path.dirname(file), spec));
    else if (/^node:|^gl(\/|$)/.test(spec)) bad.push(`${path.relative(root, file)} imports ${spec}`);
  }
};
visit(path.join(root, process.argv[2]));
if (bad.length) {
  console.error(bad.join('\n'));
  process.exit(1);
}
console.log(`${process.argv[2]} and the ${seen.size - 1} chunks it imports statically import no Node-only module`);
EOF
node browser-safe.cjs index.js || fail "tissue-sheet (the main entry) imports a Node-only module"
node browser-safe.cjs element.js || fail "tissue-sheet/element imports a Node-only module"
! node browser-safe.cjs node.js >/dev/null 2>&1 || fail "browser-safe.cjs finds no Node import even in node.js"

step "every runtime dependency is imported by the packed code"
cat > deps-used.cjs <<'EOF'
const fs = require('fs'), path = require('path');
const pkg = path.resolve('node_modules/tissue-sheet');
const manifest = JSON.parse(fs.readFileSync(path.join(pkg, 'package.json'), 'utf8'));
const code = fs.readdirSync(path.join(pkg, 'dist/esm'), { recursive: true })
  .filter((f) => f.endsWith('.js') && !f.startsWith('assets'))
  .map((f) => fs.readFileSync(path.join(pkg, 'dist/esm', f), 'utf8'))
  .join('\n');
const names = Object.keys({ ...manifest.dependencies, ...manifest.optionalDependencies });
const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
const unused = names.filter((name) => !new RegExp(`(from |import\\(|require(\\.resolve)?\\()["']${escape(name)}(/[^"']*)?["']`).test(code));
if (unused.length) {
  console.error(`dependencies no packed module imports: ${unused.join(', ')}`);
  process.exit(1);
}
console.log(`all ${names.length} runtime dependencies are imported: ${names.join(', ')}`);
EOF
node deps-used.cjs || fail "a runtime dependency is not used; make it a devDependency or remove it"

step "typecheck a consumer (moduleResolution nodenext)"
cat > consumer.ts <<'EOF'
import { runSheet, validateConfig, type SheetResult } from 'tissue-sheet';
import { createHeadlessContext } from 'tissue-sheet/node';
export async function cellCount(json: unknown): Promise<number> {
  const { result }: { result: SheetResult } = await runSheet(validateConfig(json), createHeadlessContext());
  return result.cells.length;
}
// @ts-expect-error the declarations are real types, not `any`
export const notANumber: number = runSheet;
EOF
"$repo/node_modules/.bin/tsc" --noEmit --strict --skipLibCheck --target es2022 --module nodenext \
  --moduleResolution nodenext --types node --typeRoots "$repo/node_modules/@types" consumer.ts
echo "consumer.ts typechecks"

# "engine": "gpu", so that the run goes through headless-gl (auto may pick the exact CPU engine).
cat > small.json <<'EOF'
{ "surface": { "kind": "tube", "radius": 40, "length": 400 }, "resolution": 256, "cells": 60, "seed": 9,
  "engine": "gpu", "lloyd": { "maxIterations": 3 }, "sheet": { "surfaceRatio": 1.8, "layers": 1 } }
EOF

step "npx tissue-sheet run"
npx --no-install tissue-sheet run small.json --out r.json 2> run.log || { cat run.log; fail "npx tissue-sheet run failed"; }
tail -n 1 run.log
node -e "
  const r = JSON.parse(require('fs').readFileSync('r.json', 'utf8'));
  if (r.software.name !== 'tissue-sheet' || r.cells.length !== 60) { console.error('unexpected result', r.software, r.cells.length); process.exit(1); }
  console.log('r.json:', r.cells.length, 'cells, software', r.software.name, r.software.version);
"

# $1: what is hidden, $2: a phrase the one-line message must contain.
expect_exit_3() {
  set +e
  # The bin itself, not npx: npx may add its own warnings (e.g. about the user's npm config).
  message=$(node_modules/.bin/tissue-sheet run small.json --out never.json 2>&1)
  code=$?
  set -e
  echo "exit $code: $message"
  [ "$code" -eq 3 ] || fail "$1: expected exit code 3, got $code"
  [ "$(printf '%s\n' "$message" | wc -l)" -eq 1 ] || fail "$1: expected one line"
  printf '%s' "$message" | grep -qF "$2" || fail "$1: the message does not say \"$2\""
}
step "the CLI with gl unbuilt (install script denied or failed)"
mv node_modules/gl/build "$work/gl-build"
expect_exit_3 "gl unbuilt" "npm install-scripts approve gl && npm rebuild gl"
mv "$work/gl-build" node_modules/gl/build
step "the CLI without gl (--omit=optional)"
mv node_modules/gl "$work/gl"
expect_exit_3 "gl missing" "npm install gl@"
node -e "import('tissue-sheet').then((m) => console.log('without gl, tissue-sheet still imports: runSheet', typeof m.runSheet))"
mv "$work/gl" node_modules/gl

step "check-pack: OK"
