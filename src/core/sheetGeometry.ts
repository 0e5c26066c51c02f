import { layerStepOf, steppedOffsets } from './config/methods';
import type { Config, PlanarConfig } from './config/types';
import type { Grid } from './grid';

/** One surface of the sheet's stack: the seeded surface, a layer, or the other surface. */
export interface StackSurface {
  /** "basal", "apical" or "layer k" (k = 1 next to the seeded surface). */
  readonly name: string;
  readonly role: 'seeded' | 'layer' | 'other';
  /** Signed distance from the seeded surface along its normal, µm (outward > 0). */
  readonly offset: number;
  /** Circumference relative to the seeded surface (R / R_seeded on a tube; 1 on a plane). */
  readonly ratio: number;
  readonly grid: Grid;
}

/**
 * The stack [seeded, layers..., other] of a sheet. Surfaces are parallel: the other one lies at
 * `thickness` along the seeded surface's normal (or, on a tube, at radius R·s or R/s for a
 * surface ratio s), and K layers are evenly spaced between them. A tube's surfaces are coaxial
 * cylinders: the same strip with the circumference scaled by R_k / R and square texels kept
 * (the width in texels scales too); a plane's are identical copies.
 */
export function surfaceStack(config: PlanarConfig, seededGrid: Grid): StackSurface[] {
  const { sheet, surface } = config;
  const otherName = sheet.seeded === 'basal' ? 'apical' : 'basal';
  const stack: StackSurface[] = [];
  const offsets = sheetOffsets(config);
  const count = offsets.length;
  for (let k = 0; k < count; k++) {
    const offset = offsets[k];
    const role = k === 0 ? 'seeded' : k === count - 1 ? 'other' : 'layer';
    const name = role === 'seeded' ? sheet.seeded : role === 'other' ? otherName : `layer ${k}`;
    if (surface.kind === 'plane') {
      stack.push({ name, role, offset, ratio: 1, grid: seededGrid });
      continue;
    }
    const ratio = (surface.radius + offset) / surface.radius;
    const width = Math.max(1, Math.round(seededGrid.width * ratio));
    const grid: Grid = { ...seededGrid, width, texelX: (2 * Math.PI * (surface.radius + offset)) / width };
    stack.push({ name, role, offset, ratio, grid });
  }
  return stack;
}

/**
 * Signed offsets (µm along the seeded surface's normal) of every surface of a sheet's stack
 * [seeded, layers..., other], on any surface: the one description of the stack that the
 * pipeline builds (planar and cube-map families), the run budget counts (config/limits.ts) and
 * the sweep's columns name (sweep/columns.ts). The other surface lies at `thickness` along the
 * normal (outward or inward), or on a tube at radius R·s or R/s for a surface ratio s.
 */
export function sheetOffsets(config: Config): number[] {
  const { sheet, surface } = config;
  const sign = sheet.direction === 'outward' ? 1 : -1;
  let otherOffset = sign * sheet.thickness;
  if (surface.kind === 'tube' && sheet.surfaceRatio !== null) {
    // As stackOffsets places a layer at ratio 1 + d (R·d outward, R / (1 + d) − R inward), so the
    // other surface at ratio s is the very surface a stack to a larger ratio has as its layer at
    // s (the lab's validity layers: one exact diagram serves both): R·(s − 1), not R·s − R, which
    // can differ from it in the last bit.
    const R = surface.radius;
    otherOffset = sign > 0 ? R * (sheet.surfaceRatio - 1) : R / sheet.surfaceRatio - R;
  }
  return stackOffsets(config, otherOffset);
}

/**
 * Signed offsets of the stack [seeded, layers..., other] whose other surface is at
 * `otherOffset`: sheet.layers evenly spaced, or a fixed layer step (sheet.layerStep, or the lab
 * protocol's): in surface-ratio units on a tube (s = 1, 1 + step, ..., the other surface), in µm
 * of thickness elsewhere (planes and closed surfaces).
 */
function stackOffsets(config: Config, otherOffset: number): number[] {
  const { sheet, surface } = config;
  const step = layerStepOf(sheet);
  if (step === null) {
    const count = sheet.layers + 2;
    return Array.from({ length: count }, (_, k) => (otherOffset * k) / (count - 1));
  }
  if (surface.kind === 'tube') {
    const R = surface.radius;
    const otherRatio = (R + otherOffset) / R;
    const up = otherRatio >= 1;
    // Ratios 1, 1 + step, ... outward; 1, 1 / (1 + step), ... inward (the inner tube is the seeded one scaled down).
    const steps = steppedOffsets(up ? otherRatio - 1 : 1 / otherRatio - 1, step);
    return steps.map((d, k) => (k === steps.length - 1 ? otherOffset : up ? R * d : R / (1 + d) - R));
  }
  const sign = otherOffset < 0 ? -1 : 1;
  return steppedOffsets(Math.abs(otherOffset), step).map((d) => sign * d);
}

/**
 * Projects sites (interleaved x, y texel units of `from`) along the normal onto the surface with
 * grid `to`: the same angle around a tube (x scaled by the texel counts), the same y.
 */
export function projectSites(from: Grid, to: Grid, sites: Float32Array): Float32Array {
  const out = new Float32Array(sites.length);
  const scale = to.width / from.width;
  for (let i = 0; i < sites.length; i += 2) {
    out[i] = Math.min(sites[i] * scale, to.width * (1 - Number.EPSILON));
    out[i + 1] = sites[i + 1];
  }
  return out;
}
