import { Delaunay } from 'd3-delaunay';

/**
 * Exact Lloyd iterations on the CPU with d3-delaunay, on an open rectangle: what a web developer
 * would otherwise write. Sites are interleaved x, y; updated in place. Returns ms per iteration.
 */
export function cpuLloydIterations(sites: Float64Array, width: number, height: number, iterations: number): number {
  const start = performance.now();
  const delaunay = new Delaunay(sites);
  const voronoi = delaunay.voronoi([0, 0, width, height]);
  const count = sites.length / 2;
  for (let iteration = 0; iteration < iterations; iteration++) {
    for (let i = 0; i < count; i++) {
      const polygon = voronoi.cellPolygon(i);
      if (!polygon) continue;
      let area = 0;
      let cx = 0;
      let cy = 0;
      for (let k = 0; k < polygon.length - 1; k++) {
        const [x0, y0] = polygon[k];
        const [x1, y1] = polygon[k + 1];
        const cross = x0 * y1 - x1 * y0;
        area += cross;
        cx += (x0 + x1) * cross;
        cy += (y0 + y1) * cross;
      }
      sites[2 * i] = cx / (3 * area);
      sites[2 * i + 1] = cy / (3 * area);
    }
    delaunay.update();
    voronoi.update();
  }
  return (performance.now() - start) / iterations;
}
