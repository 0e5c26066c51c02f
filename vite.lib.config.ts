import { defineConfig } from 'vite';

/**
 * Library build of the `<tissue-sheet>` web component: one self-contained ES module
 * (three.js, ajv and d3-delaunay bundled) at dist/lib/tissue-sheet.js. Type declarations are
 * emitted next to it by `tsc -p tsconfig.lib.json` (see the "build:lib" script).
 */
export default defineConfig({
  publicDir: false,
  build: {
    target: 'es2022',
    outDir: 'dist/lib',
    emptyOutDir: true,
    sourcemap: true,
    lib: {
      entry: 'src/element/index.ts',
      formats: ['es'],
      fileName: () => 'tissue-sheet.js',
    },
  },
});
