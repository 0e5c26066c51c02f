#!/usr/bin/env bash
# Installs the project and starts the app at http://127.0.0.1:5173/
# (headless-gl is an optional dependency the app does not use: without a C++ compiler its build
# fails and npm ci goes on without it.)
set -euo pipefail
cd "$(dirname "$0")/.."
npm ci --no-audit --no-fund
exec npm start
