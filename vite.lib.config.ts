import { readFileSync } from 'node:fs';
import { defineConfig } from 'vite';

/**
 * Two library builds (the app has its own config, vite.config.ts):
 *
 * - default: the npm package's modules in dist/ — `index.js` (the browser-safe library),
 *   `node.js` (headless-gl context, PNG files), `element.js` (defines `<tissue-sheet>`) and
 *   `cli.js` (what bin/tissue-sheet.mjs runs), sharing chunks in dist/chunks/. Dependencies and
 *   Node built-ins stay imports, so a consumer's bundler dedupes three.js and `gl` is loaded only
 *   by the Node code that asks for a context. Type declarations: `tsc -p tsconfig.lib.json`.
 * - `--mode standalone`: the `<tissue-sheet>` element as one self-contained ES module (three.js
 *   and d3-delaunay bundled) at dist/lib/tissue-sheet.js, for a plain <script type="module">.
 *   ajv is a build-time tool only: the validators are precompiled to plain code
 *   (scripts/validators.ts), so neither build carries ajv.
 */
const packageJson = JSON.parse(readFileSync(new URL('./package.json', import.meta.url), 'utf8')) as {
  dependencies?: Record<string, string>;
  optionalDependencies?: Record<string, string>;
};
const dependencies = Object.keys({ ...packageJson.dependencies, ...packageJson.optionalDependencies });
/** `three` and `three/addons/...`, `node:fs`, ...: imports the package keeps rather than bundles. */
const isExternal = (id: string) =>
  id.startsWith('node:') || dependencies.some((name) => id === name || id.startsWith(name + '/'));

export default defineConfig(({ mode }) =>
  mode === 'standalone'
    ? {
        publicDir: false,
        base: './',
        build: {
          target: 'es2022',
          outDir: 'dist/lib',
          emptyOutDir: true,
          sourcemap: true,
          lib: { entry: 'src/element/index.ts', formats: ['es'], fileName: () => 'tissue-sheet.js' },
        },
      }
    : {
        publicDir: false,
        // Asset URLs (the pipeline worker) relative to the module that loads them, not to the
        // page's origin: `new URL('../assets/pipelineWorker-….js', import.meta.url)`.
        base: './',
        // The worker is a self-contained asset (three.js bundled in): minified, unlike the modules.
        worker: { rollupOptions: { output: { minify: true } } },
        build: {
          target: 'es2022',
          outDir: 'dist/esm',
          // Only this build writes dist/esm (the standalone is dist/lib, the app dist/app).
          emptyOutDir: true,
          minify: false,
          lib: {
            entry: {
              index: 'src/index.ts',
              node: 'src/node/index.ts',
              element: 'src/element/index.ts',
              cli: 'src/cli/main.ts',
            },
            formats: ['es'],
            fileName: (_format, name) => `${name}.js`,
          },
          rollupOptions: {
            external: isExternal,
            output: { chunkFileNames: 'chunks/[name]-[hash].js' },
          },
        },
      },
);
