import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { validateConfig, type ClosedConfig } from '../../src/core/config';
import { runSheet } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';
import { MESH_DIR, meshInputs } from '../mesh/helpers';

const context = useHeadlessContext();

describe('geodesic option: heat method vs the GPU geometry-image Voronoi', () => {
  it('14 sites on level-set-blob.ply (9002 vertices): timed, agreement reported', async () => {
    const config = validateConfig({
      surface: { kind: 'mesh', src: join(MESH_DIR, 'level-set-blob.ply'), scale: 50, geodesic: true },
      resolution: 64,
      cells: 14,
      lloyd: { maxIterations: 10 },
      sheet: { adjacency: 'labels' },
    }) as ClosedConfig;
    const { result } = await runSheet(config, context, meshInputs(config));
    const g = result.closed!.geodesic!;
    console.log(
      `heat method, ${g.sites} sites on ${g.vertices} vertices: setup ${g.setupMs.toFixed(0)} ms, solves ${g.solveMs.toFixed(0)} ms (${g.msPerSite.toFixed(1)} ms per site); ` +
        `GPU geometry-image Voronoi (cold flood + readback) ${g.gpuVoronoiMs.toFixed(1)} ms; agreement ${(100 * g.agreement).toFixed(2)} % of vertices; ` +
        `parameterization ${result.closed!.mesh!.parameterizationMs.toFixed(0)} ms, sampling ${result.closed!.mesh!.samplingMs.toFixed(0)} ms`,
    );
    expect(g.vertices).toBe(9002);
    expect(g.sites).toBe(14);
    // Well under the seed's ~1 s per site.
    expect(g.msPerSite).toBeLessThan(250);
    // 3D Euclidean vs geodesic cells differ only near boundaries on a smooth blob.
    expect(g.agreement).toBeGreaterThan(0.9);
  }, 30000);
});
