import { defineConfig } from 'vitest/config';

// The app (index.html), test pages (e2e/pages) and benchmark page (bench/page) are all
// served by this one config; `npm run build` builds the app (into dist/app) and the library
// (vite.lib.config.ts: dist/esm, dist/types, dist/lib).
export default defineConfig({
  server: { host: '127.0.0.1', port: 5173, strictPort: true },
  build: { target: 'es2022', outDir: 'dist/app' },
  // Scan every page up front: otherwise Vite discovers a dependency on first load, re-optimizes
  // and reloads the page under a running test.
  // Workers' dependencies (the measuring worker's decoders, the exact engine's predicates and
  // triangulation in the pipeline worker) are imported by no page module, so the scan cannot see
  // them: every browser-side runtime dependency is listed (a reload in a fresh checkout's first
  // measure-and-compare run failed an e2e test otherwise).
  optimizeDeps: {
    entries: ['index.html', 'e2e/pages/*.html', 'bench/page/*.html', 'examples/*.html'],
    include: ['d3-delaunay', 'fast-png', 'fflate', 'robust-predicates', 'three', 'three-mesh-bvh', 'tiff'],
  },
  test: {
    include: ['tests/**/*.test.ts'],
    // headless-gl is a native module: one process per test file, not worker threads.
    pool: 'forks',
    testTimeout: 120_000,
    hookTimeout: 120_000,
  },
});
