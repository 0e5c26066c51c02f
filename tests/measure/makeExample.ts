/**
 * Writes examples/measure/: a synthetic tube segment (Voronoi 4: random sites, 3 Lloyd iterations,
 * 150 cells) as 16-bit label PNGs, basal 300 x 400 px and apical twice as wide (surface ratio 2),
 * labels 1001.. (not consecutive from 0), for trying `tissue-sheet measure`:
 *
 *   node --import tsx tests/measure/makeExample.ts
 *   tissue-sheet measure examples/measure/basal.png examples/measure/apical.png --out r.json --pixel-size 0.5 --periodic-x --compare
 */
import { mkdirSync, writeFileSync } from 'node:fs';
import { exactVoronoi } from '../../src/core/exact';
import { placeSites } from '../../src/core/sites';
import { png16, rasterizeVoronoi } from './images';

const W = 300;
const H = 400;
const n = 150;
const grid = { width: W, height: H, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
let s = Float64Array.from(placeSites(grid, n, 2024, 1.5));
for (let i = 0; i < 3; i++) s = Float64Array.from(exactVoronoi(grid, s).centroids);
const sites = Array.from({ length: n }, (_, i) => [s[2 * i], s[2 * i + 1]]);
const labels = sites.map((_, i) => 1001 + 3 * i);
mkdirSync('examples/measure', { recursive: true });
writeFileSync('examples/measure/basal.png', png16(rasterizeVoronoi(W, H, sites, labels, true)));
writeFileSync(
  'examples/measure/apical.png',
  png16(
    rasterizeVoronoi(
      2 * W,
      H,
      sites.map(([x, y]) => [2 * x, y]),
      labels,
      true,
    ),
  ),
);
