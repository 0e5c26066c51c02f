/**
 * Random sites on a closed surface (placeClosedSites, src/core/closed/geometry.ts): a spacing
 * the surface cannot hold, below the up-front jamming check (feasibility.ts) but jammed in
 * practice, is a ConfigError naming minSpacing (the CLI's exit 2, a sweep's recorded point),
 * never a plain Error (exit 1).
 */
import { describe, expect, it } from 'vitest';
import { placeClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector } from '../../src/core/closed/projector';
import { ConfigError } from '../../src/core/config';
import { sampleSurface } from '../../src/core/cubemap/sample';

describe('placeClosedSites', () => {
  const image = sampleSurface({ kind: 'sphere', radius: 30 }, 200);
  const projector = ellipsoidProjector(30, 30, 30);

  it('places every site at least minSpacing apart where the sphere holds them', () => {
    const sites = placeClosedSites(image, projector, 200, 1, 4);
    let closest = Infinity;
    for (let i = 0; i < 200; i++)
      for (let j = 0; j < i; j++) {
        const d = Math.hypot(...[0, 1, 2].map((c) => sites.positions[3 * i + c] - sites.positions[3 * j + c]));
        closest = Math.min(closest, d);
      }
    expect(closest).toBeGreaterThanOrEqual(4);
    expect(new Set(sites.texels).size).toBe(200);
  });

  it('a spacing that jams (200 cells 6.2 µm apart on a 30 µm sphere: 53 % disk coverage) is a ConfigError on minSpacing', () => {
    let error: unknown = null;
    try {
      placeClosedSites(image, projector, 200, 1, 6.2);
    } catch (caught) {
      error = caught;
    }
    expect(error).toBeInstanceOf(ConfigError);
    expect((error as ConfigError).field).toBe('minSpacing');
    expect((error as Error).message).toMatch(/^minSpacing: could place only \d+ of 200 sites at least 6.2 µm apart; lower minSpacing or cells$/);
  });
});
