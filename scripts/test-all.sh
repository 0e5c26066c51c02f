#!/usr/bin/env bash
# Installs everything the tests need on a fresh Debian 12 machine (as root) and runs every test:
# typecheck, Vitest (headless-gl under Xvfb), Playwright (Debian's Chromium), then the npm
# package as a consumer installs it (scripts/check-pack.sh, about a minute; needs the registry),
# then the Python package (scripts/test-python.sh, about 5 minutes; needs PyPI).
set -euo pipefail
cd "$(dirname "$0")/.."

need=()
command -v xvfb-run >/dev/null || need+=(xvfb xauth)
[ -e /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so ] || need+=(libgl1-mesa-dri)
command -v chromium >/dev/null || need+=(chromium)
# headless-gl (gl) compiles its native module with node-gyp.
command -v g++ >/dev/null || need+=(g++)
command -v make >/dev/null || need+=(make)
command -v python3 >/dev/null || need+=(python3)
# The Python package's venvs (scripts/test-python.sh): Debian's python3 is externally managed.
python3 -c 'import ensurepip, venv' 2>/dev/null || need+=(python3-venv)
if [ ${#need[@]} -gt 0 ]; then
  echo "== installing system packages: ${need[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi

echo "== npm ci (builds headless-gl from source)"
npm ci --no-audit --no-fund

echo "== npm audit --omit=dev (the runtime dependencies; SECURITY.md)"
# Advisories are printed, never fail the run; where no registry answers audits (a closed
# network, a mirror without the audit endpoint) that is said instead.
audit_out=$(npm audit --omit=dev 2>&1) && audit_rc=0 || audit_rc=$?
if [ "$audit_rc" -eq 0 ]; then
  echo "npm audit: no known advisory in the runtime dependencies"
elif grep -qiE 'audit endpoint|ENOTFOUND|ECONNREFUSED|ETIMEDOUT|EAI_AGAIN|network|registry' <<<"$audit_out" && ! grep -q 'vulnerabilit' <<<"$audit_out"; then
  echo "npm audit: skipped, no registry answers audit requests from this machine"
else
  echo "$audit_out"
  echo "npm audit: advisories above (reported, not failing the tests; see SECURITY.md)"
fi

echo "== build: the app (dist/app) and the package (dist/esm, dist/types, dist/lib)"
npm run build

echo "== tests"
npm test

echo "== the package as a consumer installs it"
npm run check:pack

echo "== the Python package: wheel in a fresh venv, pytest, the widget in JupyterLab (docs/python.md)"
npm run test:python
