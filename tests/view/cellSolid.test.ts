/**
 * The picked cell as a solid (src/view/cellSolid.ts) on stacks from real runs: closed and
 * consistently oriented meshes, exact volumes and cross-sections on planes and tubes, scutoids
 * with different corner counts per surface, and the traced restricted Voronoi cells of a sphere.
 */
import { describe, expect, it } from 'vitest';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { runSheet } from '../../src/run/runSheet';
import { cellSolid, type CellSolid } from '../../src/view/cellSolid';
import { signedVolume } from '../../src/core/mesh/types';
import { surfacePolygons } from '../../src/view/cellPolygons';
import { viewStack, type ViewStack } from '../../src/view/stack';
import { useHeadlessContext } from '../gpu/context';

/** Area of a polygon given as interleaved x, y (positive counter-clockwise). */
function polygonArea(polygon: ArrayLike<number>): number {
  let area = 0;
  const n = polygon.length / 2;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    area += polygon[2 * i] * polygon[2 * j + 1] - polygon[2 * j] * polygon[2 * i + 1];
  }
  return area / 2;
}

const context = useHeadlessContext();

async function stackOf(input: ConfigInput): Promise<ViewStack> {
  return viewStack(await runSheet(validateConfig(input), context));
}

/** Every undirected edge used exactly twice, once in each direction. */
function expectClosed(solid: CellSolid): void {
  const directed = new Map<string, number>();
  const { indices } = solid;
  for (let t = 0; t < indices.length; t += 3) {
    for (let e = 0; e < 3; e++) {
      const key = `${indices[t + e]},${indices[t + ((e + 1) % 3)]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  for (const [key, count] of directed) {
    expect(count, key).toBe(1);
    const [a, b] = key.split(',');
    expect(directed.get(`${b},${a}`), `${key} reversed`).toBe(1);
  }
  expect(signedVolume(solid)).toBeGreaterThan(0);
  for (const v of solid.normals) expect(Number.isFinite(v)).toBe(true);
}

const tubeConfig = {
  surface: { kind: 'tube', radius: 256 / (2 * Math.PI), length: 256 },
  engine: 'exact',
  resolution: 128,
  cells: 40,
  minSpacing: 5,
  seed: 3,
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 2.5, layers: 1 },
} as const;

describe('cellSolid on planes and tubes (exact cross-sections)', () => {
  it('a flat sheet with parallel surfaces: a prism, volume = polygon area x thickness', async () => {
    const thickness = 7;
    const stack = await stackOf({
      surface: { kind: 'plane', width: 200, height: 160 },
      engine: 'exact',
      resolution: 128,
      cells: 30,
      seed: 5,
      lloyd: { maxIterations: 2 },
      sheet: { thickness },
    });
    let checked = 0;
    for (let id = 0; id < stack.result.cells.length; id++) {
      const solid = cellSolid(stack, id)!;
      expect(solid).not.toBeNull();
      expect(solid.exact).toBe(true);
      expectClosed(solid);
      const area = surfacePolygons(stack.surfaces[0]).cells[id].area;
      const volume = signedVolume(solid);
      expect(Math.abs(volume - area * thickness) / (area * thickness), `cell ${id}`).toBeLessThan(1e-6);
      checked++;
    }
    expect(checked).toBe(30);
  });

  it('a tube: each cross-section lies on its cylinder and, unrolled, has the exact polygon area', async () => {
    const stack = await stackOf(tubeConfig);
    expect(stack.surfaces.length).toBe(3);
    const radius = tubeConfig.surface.radius;
    for (let id = 0; id < stack.result.cells.length; id++) {
      const solid = cellSolid(stack, id)!;
      expectClosed(solid);
      solid.sections.forEach((section, k) => {
        const surface = stack.surfaces[k];
        const exact = surfacePolygons(surface).cells[id];
        // The traced outline, in µm of the unrolled surface.
        expect(Math.abs(polygonArea(section.outline) - exact.area) / exact.area).toBeLessThan(1e-9);
        // The 3D ring, on the cylinder of radius R + offset, unrolled (arc length, z).
        const r = radius + surface.offset;
        const unrolled = new Float64Array(2 * solid.rays);
        let reference = NaN;
        for (let i = 0; i < solid.rays; i++) {
          const v = section.centre + 1 + i;
          const x = solid.positions[3 * v] + solid.origin[0];
          const y = solid.positions[3 * v + 1] + solid.origin[1];
          const z = solid.positions[3 * v + 2] + solid.origin[2];
          expect(Math.abs(Math.hypot(x, y) - r) / r).toBeLessThan(1e-5);
          let angle = Math.atan2(y, x);
          if (Number.isNaN(reference)) reference = angle;
          angle = reference + Math.atan2(Math.sin(angle - reference), Math.cos(angle - reference));
          unrolled[2 * i] = angle * r;
          unrolled[2 * i + 1] = z;
        }
        expect(Math.abs(Math.abs(polygonArea(unrolled)) - exact.area) / exact.area).toBeLessThan(1e-4);
      });
    }
  });

  it('a scutoid: different corner counts at the two surfaces, still one closed solid', async () => {
    const stack = await stackOf(tubeConfig);
    const last = stack.surfaces.length - 1;
    let scutoids = 0;
    for (let id = 0; id < stack.result.cells.length; id++) {
      const first = surfacePolygons(stack.surfaces[0]).cells[id];
      const other = surfacePolygons(stack.surfaces[last]).cells[id];
      if (first.border || other.border) continue;
      if (first.neighbours.length === other.neighbours.length) continue;
      const solid = cellSolid(stack, id)!;
      expect(solid.sections[0].corners).toBe(first.polygon.length / 2);
      expect(solid.sections[last].corners).toBe(other.polygon.length / 2);
      expect(solid.sections[0].corners).not.toBe(solid.sections[last].corners);
      expectClosed(solid);
      scutoids++;
    }
    expect(scutoids).toBeGreaterThan(0);
  });

  it('returns null for an id out of range', async () => {
    const stack = await stackOf(tubeConfig);
    expect(cellSolid(stack, -1)).toBeNull();
    expect(cellSolid(stack, stack.result.cells.length)).toBeNull();
  });
});

describe('cellSolid on closed surfaces (traced restricted Voronoi cells)', () => {
  it('a sphere shell: closed, and its volume between the inner and outer cross-sections times the thickness', async () => {
    const radius = 40;
    const thickness = 6;
    const stack = await stackOf({
      surface: { kind: 'sphere', radius },
      resolution: 32,
      cells: 60,
      seed: 2,
      lloyd: { maxIterations: 2 },
      sheet: { thickness },
    });
    expect(stack.closed).toBe(true);
    const last = stack.surfaces.length - 1;
    for (let id = 0; id < stack.result.cells.length; id += 7) {
      const solid = cellSolid(stack, id)!;
      expect(solid.exact).toBe(false);
      expectClosed(solid);
      // Every traced point lies on its sphere.
      solid.sections.forEach((section, k) => {
        const r = radius + stack.surfaces[k].offset;
        for (let i = 0; i <= solid.rays; i++) {
          const v = 3 * (section.centre + i);
          const d = Math.hypot(solid.positions[v] + solid.origin[0], solid.positions[v + 1] + solid.origin[1], solid.positions[v + 2] + solid.origin[2]);
          expect(Math.abs(d - r) / r).toBeLessThan(1e-5);
        }
      });
      // Concentric spheres: the cell is a cone section; its volume lies between the inner and
      // outer cap areas (flat fans) times the thickness.
      const inner = fanArea(solid, 0);
      const outer = fanArea(solid, last);
      const volume = signedVolume(solid);
      expect(volume).toBeGreaterThan(inner * thickness);
      expect(volume).toBeLessThan(outer * thickness);
    }
    // The traced cells tile the sphere: their caps add up to its area (flat fans: a little less).
    let total = 0;
    for (let id = 0; id < stack.result.cells.length; id++) total += fanArea(cellSolid(stack, id)!, 0);
    const sphereArea = 4 * Math.PI * radius ** 2;
    expect(total / sphereArea).toBeGreaterThan(0.97);
    expect(total / sphereArea).toBeLessThan(1.001);
  });

  it('an ellipsoid with a layer: closed, oriented, positive volume, points near the geometry image', async () => {
    const stack = await stackOf({
      surface: { kind: 'ellipsoid', a: 60, b: 40, c: 35 },
      resolution: 32,
      cells: 50,
      seed: 4,
      lloyd: { maxIterations: 1 },
      sheet: { thickness: 4, layers: 1 },
    });
    expect(stack.surfaces.length).toBe(3);
    for (let id = 0; id < stack.result.cells.length; id += 5) {
      const solid = cellSolid(stack, id)!;
      expectClosed(solid);
      const { a, b, c } = { a: 60, b: 40, c: 35 };
      const v = 3 * (solid.sections[0].centre + 1);
      const [x, y, z] = [0, 1, 2].map((k) => solid.positions[v + k] + solid.origin[k]);
      expect(Math.abs(Math.sqrt((x / a) ** 2 + (y / b) ** 2 + (z / c) ** 2) - 1)).toBeLessThan(0.01);
    }
  });
});

/** Area of a section's fan of triangles from its site. */
function fanArea(solid: CellSolid, k: number): number {
  const { positions } = solid;
  const c = solid.sections[k].centre;
  const at = (v: number) => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
  let area = 0;
  for (let i = 0; i < solid.rays; i++) {
    const [o, a, b] = [at(c), at(c + 1 + i), at(c + 1 + ((i + 1) % solid.rays))];
    const u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
    const w = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
    area += Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / 2;
  }
  return area;
}
