import { statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig, type ClosedConfig, type ConfigInput } from '../../src/core/config';
import { icosphere, mapVertices } from '../../src/core/mesh/generate';
import { writePlyAscii } from '../../src/core/mesh/write';
import { runSheet } from '../../src/run/runSheet';
import type { SheetResult } from '../../src/run/result';
import { useHeadlessContext } from '../gpu/context';
import { loadMeshFile } from '../../src/node/meshFile';
import { MESH_DIR, meshInputs, surfaceArea } from '../mesh/helpers';

const context = useHeadlessContext();
const closed = (input: ConfigInput) => validateConfig(input) as ClosedConfig;

describe('a mesh of a sphere vs the analytic sphere', () => {
  it('gives the same statistics within sampling error', async () => {
    const R = 50;
    const sheet = { thickness: 15, adjacency: 'labels' } as const;
    const common = { resolution: 64, cells: 300, minSpacing: 4, lloyd: { maxIterations: 25 }, sheet };
    const sphere = (await runSheet(closed({ ...common, surface: { kind: 'sphere', radius: R } }), context)).result;
    const ico = writePlyAscii(icosphere(16)); // 2562 vertices, unit radius
    const mesh = (
      await runSheet(closed({ ...common, surface: { kind: 'mesh', src: 'icosphere16.ply', scale: R } }), context, {
        meshFile: { data: ico, name: 'icosphere16.ply' },
      })
    ).result;
    const a = sphere.analyses[0].summary,
      b = mesh.analyses[0].summary;
    const cells = 300;
    const hexA = a.perSurface[0].polygonDistribution[3],
      hexB = b.perSurface[0].polygonDistribution[3];
    // Two independent samples of a proportion: SE of the difference sqrt(2 p (1 - p) / N).
    const se = Math.sqrt((2 * hexA * (1 - hexA)) / cells);
    console.log(
      `sphere vs icosphere mesh (R = ${R} µm, 300 cells, thickness 15 µm): hexagons ${hexA.toFixed(3)} vs ${hexB.toFixed(3)} (SE of difference ${se.toFixed(3)}); ` +
        `mean sides ${a.perSurface[0].meanSides.toFixed(3)} vs ${b.perSurface[0].meanSides.toFixed(3)}; % scutoids ${a.percentScutoids.toFixed(2)} vs ${b.percentScutoids.toFixed(2)}; ` +
        `mean transitions ${a.meanTransitions.toFixed(3)} vs ${b.meanTransitions.toFixed(3)}; area ${sphere.closed!.area.toFixed(1)} vs ${mesh.closed!.area.toFixed(1)}`,
    );
    expect(Math.abs(hexA - hexB)).toBeLessThanOrEqual(3 * se);
    expect(Math.abs(a.perSurface[0].meanSides - b.perSurface[0].meanSides)).toBeLessThanOrEqual(0.05);
    // Concentric: the analytic sphere has none; the mesh's faceted normals may make a few.
    expect(a.percentScutoids).toBe(0);
    expect(b.percentScutoids).toBeLessThanOrEqual(3);
    expect(mesh.closed?.kind).toBe('mesh');
    expect(mesh.closed?.mesh?.vertices).toBe(2562);
    // Mesh area of the flat-faceted icosphere is slightly below 4πR².
    expect(mesh.closed!.area / (4 * Math.PI * R * R)).toBeGreaterThan(0.99);
  }, 20000);
});

describe('cells of a mesh are uniform in mesh area', () => {
  it('egg-chamber.ply (parameterization area ratio 0.19..1.83): cell areas on the mesh', async () => {
    const config = closed({
      surface: { kind: 'mesh', src: join(MESH_DIR, 'egg-chamber.ply'), scale: 40 },
      resolution: 96,
      cells: 200,
      minSpacing: 5,
      lloyd: { maxIterations: 40, overRelaxation: 1.9 },
      sheet: { thickness: 0 },
    });
    const { result } = await runSheet(config, context, meshInputs(config));
    const areas = result.cells.map((c) => c.area);
    const mean = areas.reduce((x, y) => x + y) / areas.length;
    const sd = Math.sqrt(areas.reduce((s, x) => s + (x / mean - 1) ** 2, 0) / areas.length);
    const sorted = areas.map((x) => x / mean).sort((x, y) => x - y);
    const total = areas.reduce((x, y) => x + y);
    console.log(
      `egg-chamber mesh, 200 cells: cell area SD ${sd.toFixed(4)} of the mean, IQR/2 ${((sorted[149] - sorted[49]) / 2).toFixed(4)}, min ${sorted[0].toFixed(3)}, max ${sorted[199].toFixed(3)}; distortion of the map ${JSON.stringify(result.closed?.mesh?.areaDistortion)}`,
    );
    expect(total / result.closed!.area).toBeCloseTo(1, 6);
    expect(sd).toBeLessThanOrEqual(0.1);
    expect((sorted[149] - sorted[49]) / 2).toBeLessThanOrEqual(0.06);
  }, 20000);
});

describe('malformed meshes get their message through the pipeline', () => {
  const messageOf = async (input: ConfigInput): Promise<ConfigError> => {
    try {
      const config = closed(input);
      await runSheet(config, context, meshInputs(config));
    } catch (e) {
      return e as ConfigError;
    }
    throw new Error('no error');
  };
  it('open mesh', async () => {
    const e = await messageOf({ surface: { kind: 'mesh', src: join(MESH_DIR, 'open-sphere.ply') }, resolution: 32, cells: 10 });
    expect(e).toBeInstanceOf(ConfigError);
    expect(e.field).toBe('surface.src');
    expect(e.message).toMatch(/^surface\.src: .*open-sphere\.ply: not closed: \d+ boundary edges .* forming 1 hole/);
    expect(e.message).not.toContain('\n');
  });
  it('torus: genus 1', async () => {
    const e = await messageOf({ surface: { kind: 'mesh', src: 'torus.ply' }, resolution: 32, cells: 10 });
    expect(e.field).toBe('surface.src');
    expect(e.message).toMatch(/torus\.ply: genus 1: /);
    expect(e.message).toContain('tissue-sheet needs a closed surface without holes (genus 0)');
  });
  it('a file that is not a mesh, and a missing file', async () => {
    const bad = await runSheet(closed({ surface: { kind: 'mesh', src: 'x.ply' }, resolution: 32, cells: 10 }), context, {
      meshFile: { data: 'ply\nformat ascii 1.0\nelement vertex 2\n', name: 'x.ply' },
    }).catch((e: unknown) => e as ConfigError);
    expect((bad as ConfigError).field).toBe('surface.src');
    expect((bad as ConfigError).message).toMatch(/^surface\.src: x\.ply: /);
    const missing = await messageOf({ surface: { kind: 'mesh', src: 'no-such-mesh.ply' }, resolution: 32, cells: 10 });
    expect(missing.message).toContain('cannot find "no-such-mesh.ply"');
    expect(() => loadMeshFile(MESH_DIR)).toThrow(/is a directory/);
  });
  it("finds a sample mesh by its name from any working directory (the package's public/meshes/)", () => {
    const here = process.cwd();
    try {
      process.chdir(tmpdir());
      const sample = loadMeshFile('organoid.ply', tmpdir());
      expect(sample.name).toBe(join(MESH_DIR, 'organoid.ply'));
      expect((sample.data as ArrayBuffer).byteLength).toBe(statSync(join(MESH_DIR, 'organoid.ply')).size);
    } finally {
      process.chdir(here);
    }
  });
  it('the pipeline reads no file: a mesh config without its loaded file is refused, naming what to do', async () => {
    const e = (await runSheet(closed({ surface: { kind: 'mesh', src: join(MESH_DIR, 'organoid.ply') }, resolution: 32, cells: 10 }), context).catch(
      (x: unknown) => x,
    )) as ConfigError;
    expect(e).toBeInstanceOf(ConfigError);
    expect(e.field).toBe('surface.src');
    expect(e.message).toMatch(/is not loaded: the pipeline reads no files; load the mesh first/);
  });
  it('a mesh inside out is flipped, not refused; an inward offset beyond its curvature is refused', async () => {
    const flipped = mapVertices(icosphere(6), ([x, y, z]) => [x, y, z]);
    const t = flipped.indices;
    for (let f = 0; f < t.length; f += 3) [t[f + 1], t[f + 2]] = [t[f + 2], t[f + 1]];
    const data = writePlyAscii(flipped);
    const ok: SheetResult = (
      await runSheet(closed({ surface: { kind: 'mesh', src: 'in.ply', scale: 20 }, resolution: 32, cells: 20, lloyd: { maxIterations: 2 } }), context, {
        meshFile: { data, name: 'in.ply' },
      })
    ).result;
    expect(ok.closed!.area).toBeCloseTo(surfaceArea(flipped) * 400, -1);
    const e = await runSheet(
      closed({ surface: { kind: 'mesh', src: 'in.ply', scale: 20 }, resolution: 32, cells: 20, sheet: { direction: 'inward', thickness: 25 } }),
      context,
      { meshFile: { data, name: 'in.ply' } },
    ).catch((x: unknown) => x as ConfigError);
    expect((e as ConfigError).field).toBe('sheet.thickness');
    expect((e as ConfigError).message).toContain('mesh (estimated from its vertex normals)');
  });
});
