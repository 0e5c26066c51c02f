#!/usr/bin/env bash
# The Python package (python/, issue 29): builds its sdist and wheel, installs the wheel into a
# fresh venv with what the tests need from PyPI (python/requirements-test.txt, pinned), and runs
# pytest (readers against CLI outputs, headless calls, the example notebook, sheet.sweep waiting
# in a kernel) and the JupyterLab end-to-end test (e2e/python-jupyter.spec.ts, Debian's
# Chromium). Venvs and the built files live
# in git-ignored folders under python/. Needs the checkout built (npm ci; npm run build:lib, which
# this script runs when dist/lib is missing or older than src). About 5 minutes on 2 shared
# cores, most of it pip and the build.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

# Debian's python3 is externally managed: everything goes into venvs. python3-venv brings ensurepip.
if ! python3 -c 'import ensurepip, venv' 2>/dev/null; then
  echo "== installing python3-venv"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null
fi

# The wheel bundles dist/lib and the tests run the CLI (dist/esm): rebuild both when a source is newer.
if [ ! -f dist/lib/tissue-sheet.js ] || [ ! -f dist/esm/cli.js ] ||
  [ -n "$(find src package.json vite.lib.config.ts -newer dist/lib/tissue-sheet.js -print -quit)" ] ||
  [ -n "$(find src package.json vite.lib.config.ts -newer dist/esm/cli.js -print -quit)" ]; then
  echo "== build:lib (dist/lib, dist/esm older than src)"
  npm run build:lib
fi

echo "== python: build the sdist and the wheel (python -m build)"
rm -rf python/.venv-build python/dist
python3 -m venv python/.venv-build
python/.venv-build/bin/pip install -q --disable-pip-version-check -r python/requirements-build.txt
python/.venv-build/bin/python -m build --outdir python/dist python
wheel=$(ls python/dist/tissue_sheet-*.whl)

echo "== python: install $(basename "$wheel") into a fresh venv"
rm -rf python/.venv
python3 -m venv python/.venv
python/.venv/bin/pip install -q --disable-pip-version-check "$wheel" -r python/requirements-test.txt

echo "== python: pytest (against the installed wheel)"
export TISSUE_SHEET_CLI="$root/bin/tissue-sheet.mjs"
(cd python && TISSUE_SHEET_EXPECT_WHEEL=1 .venv/bin/pytest -q -p no:cacheprovider tests)

echo "== python: the widget in JupyterLab (Playwright, Chromium)"
TISSUE_SHEET_JUPYTER_E2E=1 TISSUE_SHEET_VENV="$root/python/.venv" npx playwright test e2e/python-jupyter.spec.ts
