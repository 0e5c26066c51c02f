import { validateConfig, type PlanarConfig } from '../src/core/config';

/**
 * validateConfig for tests that build planes and tubes and read their planar fields (width,
 * radius, length): a closed kind fails the test here instead of surfacing later as an undefined
 * field. The library itself never narrows this way: a config becomes a surface in
 * src/core/config/surfaceLayout.ts.
 */
export function validatePlanarConfig(input: unknown): PlanarConfig {
  const config = validateConfig(input);
  if (config.surface.kind !== 'plane' && config.surface.kind !== 'tube') {
    throw new Error(`tests/planarConfig: "${config.surface.kind}" is not a planar surface`);
  }
  return config as PlanarConfig;
}
