/**
 * Rules between the method fields of a config: the engine, the protocol, the layer step and the
 * contact rules. Each refusal is one line naming the field and what to change.
 */
import { LAB_PROTOCOL, MAX_PROTOCOL_LAYERS, protocolProblem } from '../analysis/protocol';
import type { Config } from './types';
import { ConfigError } from './configError';

type Sheet = Config['sheet'];

/** The layer step in force: sheet.layerStep, else the lab protocol's, else none (sheet.layers). */
export function layerStepOf(sheet: Sheet): number | null {
  return sheet.layerStep ?? (sheet.protocol === 'lab' ? LAB_PROTOCOL.layerStep : null);
}

/** The pixel contact rule in force (texel edges of a 512-px-wide image), or null for minContactLength. */
export function minContactPixelsOf(sheet: Sheet): number | null {
  return sheet.minContactPixels ?? (sheet.protocol === 'lab' && sheet.minContactLength === null ? LAB_PROTOCOL.minContactPixels : null);
}

/**
 * [0, step, 2 step, ..., total]: the offsets (or, shifted by 1, the ratios) of a stack laid out
 * at a fixed step, ending exactly at `total` (>= 0).
 */
export function steppedOffsets(total: number, step: number): number[] {
  const count = Math.floor(total / step + 1e-9);
  const offsets = Array.from({ length: count + 1 }, (_, k) => k * step);
  if (total - offsets[count] > 1e-9 * Math.max(1, total)) offsets.push(total);
  else offsets[count] = total;
  if (offsets.length === 1) offsets.push(total);
  return offsets;
}

export function checkMethods(config: Config): void {
  const { sheet, surface } = config;
  if (config.engine === 'exact' && sheet.adjacency === 'labels') {
    throw new ConfigError(
      'sheet.adjacency',
      'sheet.adjacency: "labels" needs label textures, which engine "exact" does not make; use "exact" or "both", or engine "gpu"',
    );
  }
  const problem = protocolProblem(sheet.protocol, surface.kind, sheet.surfaceRatio);
  if (problem) throw new ConfigError('sheet.protocol', problem);
  if (sheet.protocol === 'lab' && sheet.direction === 'inward') {
    throw new ConfigError(
      'sheet.direction',
      'sheet.direction: protocol "lab" steps outward from the inner (basal) tube, s >= 1; use "outward" or protocol "default"',
    );
  }
  if (sheet.minContactPixels !== null && sheet.minContactLength !== null) {
    throw new ConfigError(
      'sheet.minContactPixels',
      'sheet.minContactPixels: give either sheet.minContactPixels (texel edges) or sheet.minContactLength (µm), not both',
    );
  }
  if (sheet.minContactPixels !== null && surface.kind !== 'tube') {
    throw new ConfigError(
      'sheet.minContactPixels',
      `sheet.minContactPixels: the pixel rule counts pixels of an image 512 px around a tube; on a ${surface.kind} give sheet.minContactLength in µm instead`,
    );
  }
  if (sheet.offset === 'axes') {
    if (surface.kind !== 'sphere' && surface.kind !== 'ellipsoid') {
      throw new ConfigError('sheet.offset', `sheet.offset: "axes" grows the semi-axes of a sphere or ellipsoid; a ${surface.kind} has none: use "normal"`);
    }
    const smallest = surface.kind === 'sphere' ? surface.radius : Math.min(surface.a, surface.b, surface.c);
    if (sheet.direction === 'inward' && sheet.thickness >= smallest) {
      throw new ConfigError(
        'sheet.thickness',
        `sheet.thickness: ${sheet.thickness} µm inward would shrink the smallest semi-axis (${smallest} µm) to nothing; use less than ${smallest} µm or direction "outward"`,
      );
    }
  }
  const step = layerStepOf(sheet);
  if (step === null) return;
  if (sheet.layers > 0) {
    throw new ConfigError('sheet.layers', `sheet.layers: give either sheet.layers (${sheet.layers}) or a layer step (${step}), not both`);
  }
  let span = sheet.thickness;
  if (surface.kind === 'tube') {
    const other =
      sheet.surfaceRatio ?? (sheet.direction === 'outward' ? 1 + sheet.thickness / surface.radius : Math.max(1e-9, 1 - sheet.thickness / surface.radius));
    span = other >= 1 ? other - 1 : 1 / other - 1;
  }
  const spanOf = sheet.protocol === 'lab' ? Math.max(span, sheet.validityMaxRatio - 1) : span;
  const surfaces = Math.floor(spanOf / step) + 2;
  if (surfaces > MAX_PROTOCOL_LAYERS) {
    throw new ConfigError('sheet.layerStep', `sheet.layerStep: ${step} gives ${surfaces} surfaces (at most ${MAX_PROTOCOL_LAYERS}); raise sheet.layerStep`);
  }
}
