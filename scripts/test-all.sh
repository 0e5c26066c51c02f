#!/usr/bin/env bash
# Installs everything the tests need on a fresh Debian 12 machine (as root) and runs every test:
# typecheck, Vitest (headless-gl under Xvfb) and Playwright (Debian's Chromium).
set -euo pipefail
cd "$(dirname "$0")/.."

need=()
command -v xvfb-run >/dev/null || need+=(xvfb xauth)
[ -e /usr/lib/x86_64-linux-gnu/dri/swrast_dri.so ] || need+=(libgl1-mesa-dri)
command -v chromium >/dev/null || need+=(chromium)
if [ ${#need[@]} -gt 0 ]; then
  echo "== installing system packages: ${need[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi

echo "== npm ci (builds headless-gl from source)"
npm ci --no-audit --no-fund

echo "== tests"
npm test
