#!/usr/bin/env bash
# Installs the project and starts the app at http://127.0.0.1:5173/
set -euo pipefail
cd "$(dirname "$0")/.."
npm ci --no-audit --no-fund
exec npm start
