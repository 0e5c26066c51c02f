/**
 * Analysis protocols: which cells are valid, which layers are compared, which contacts count.
 * Every rule and its source is in docs/protocols.md.
 *
 * "default": today's behaviour. Valid = no open-end contact on the surfaces of the analysed stack;
 * layers as configured (`sheet.layers`, evenly spaced); transitions = Σ_k |N_k Δ N_k+1|.
 *
 * "lab" (Gómez-Gálvez et al. 2018, Nat. Commun., Methods; the 2021–2022 Delaunay pipeline of the
 * lab's Epithelia3D repository, script delaunayEuler3DPredefinedSeeds.m):
 * - layers at s = 1, 1 + step, ..., up to the apical ratio (step 0.25 in ratio units);
 * - valid = no open-end contact on ANY layer of s = 1 : step : validityMaxRatio (1 : 0.25 : 10),
 *   decided once per realization, so every ratio is computed on the same cells;
 * - intercalations accumulated layer to layer: transitions = |∪ lost| + |∪ won| (a neighbour
 *   lost at one layer and won back later counts once in each set); scutoid = any change on
 *   any layer; 3D neighbours = |∪_k N_k|;
 * - the labels method ignores contacts shorter than `minContactPixels` pixels of an image
 *   `referenceWidthPixels` around the seeded surface (the exact method needs no threshold).
 */
import type { Grid } from '../grid';
import { BORDER_EXCLUDED } from '../border';
import type { SurfaceAdjacency } from './adjacency';

export type ProtocolName = 'default' | 'lab';

export interface LabProtocolSettings {
  /** Step between layers, in surface-ratio units (tubes). */
  readonly layerStep: number;
  /** Validity is checked on every layer s = 1 : layerStep : validityMaxRatio. */
  readonly validityMaxRatio: number;
  /** Labels method: contacts shorter than this many pixels of the reference image are dropped. */
  readonly minContactPixels: number;
  /** Width (around the seeded surface) of the reference image the pixel rule refers to. */
  readonly referenceWidthPixels: number;
}

export const LAB_PROTOCOL: LabProtocolSettings = {
  layerStep: 0.25,
  validityMaxRatio: 10,
  minContactPixels: 6,
  referenceWidthPixels: 512,
};

/** Layers beyond this many per stack are refused (bounds the work of a config from anyone). */
export const MAX_PROTOCOL_LAYERS = 4000;

/**
 * from, from + step, ..., ending exactly at `to` (added when the steps do not land on it, and
 * never duplicated within 1e-9). Works for to < from too (steps go down).
 */
export function ratioSteps(from: number, to: number, step: number): number[] {
  if (!(step > 0) || !Number.isFinite(step)) throw new Error(`sheet.layerStep must be a positive number (got ${step})`);
  if (!(from > 0 && to > 0)) throw new Error(`surface ratios must be positive (got ${from} and ${to})`);
  const count = Math.floor(Math.abs(to - from) / step + 1e-9);
  if (count + 2 > MAX_PROTOCOL_LAYERS) {
    throw new Error(`sheet.layerStep: ${count + 1} layers from ${from} to ${to}; raise layerStep (at most ${MAX_PROTOCOL_LAYERS} layers)`);
  }
  const sign = to >= from ? 1 : -1;
  const out: number[] = [];
  for (let k = 0; k <= count; k++) out.push(from + sign * k * step);
  if (Math.abs(out[out.length - 1] - to) > 1e-9) out.push(to);
  else out[out.length - 1] = to;
  return out;
}

/** The lab's layers of a tube from the seeded surface (s = 1) to the other one (s = apicalRatio). */
export function labLayerRatios(apicalRatio: number, settings: LabProtocolSettings = LAB_PROTOCOL): number[] {
  return ratioSteps(1, apicalRatio, settings.layerStep);
}

/** The layers validity is decided on: 1 : step : validityMaxRatio (inward tubes: down to 1/max). */
export function validityRatios(settings: LabProtocolSettings = LAB_PROTOCOL, inward = false): number[] {
  if (!(settings.validityMaxRatio >= 1)) {
    throw new Error(`sheet.validityMaxRatio must be >= 1 (got ${settings.validityMaxRatio})`);
  }
  const ratios = ratioSteps(1, settings.validityMaxRatio, settings.layerStep);
  return inward ? ratios.map((s) => 1 / s) : ratios;
}

/** 1 for every cell that is a border cell (any `border` bit) on any of the surfaces. */
export function invalidOnAnySurface(surfaces: readonly Pick<SurfaceAdjacency, 'border'>[], count: number, into = new Uint8Array(count)): Uint8Array {
  for (const surface of surfaces) {
    for (let i = 0; i < count; i++) if (surface.border[i] !== 0) into[i] = 1;
  }
  return into;
}

/** The stack with the same cells excluded on every surface: those marked 1 in `invalid` (BORDER_EXCLUDED). */
export function excludeInvalid(stack: readonly SurfaceAdjacency[], invalid: Uint8Array): SurfaceAdjacency[] {
  const border = Uint8Array.from(invalid, (v) => (v ? BORDER_EXCLUDED : 0));
  return stack.map((s) => ({ ...s, border }));
}

/**
 * Where the lab protocol applies: tubes with a surface ratio. A plane's layers are identical
 * copies and closed surfaces have no open end, so "lab" is refused there with a one-line message.
 */
export function protocolProblem(protocol: ProtocolName, surfaceKind: string, surfaceRatio: number | null): string | null {
  if (protocol === 'default') return null;
  if (protocol !== 'lab') return `sheet.protocol: "${String(protocol)}" is not a protocol; use "default" or "lab"`;
  if (surfaceKind !== 'tube') {
    return `sheet.protocol: "lab" applies to tubes only (its layers and validity are in surface-ratio units); use "default" on a ${surfaceKind}`;
  }
  if (surfaceRatio === null) return 'sheet.protocol: "lab" needs sheet.surfaceRatio (the apical ratio its layers step up to); set it or use "default"';
  return null;
}

/**
 * The pixel contact rule of the labels method on `grid`, in texel edges: `minContactPixels` of an
 * image `referenceWidthPixels` around the seeded surface, scaled to this grid's texels around
 * (a contact is measured as the number of texel edges it shares: a staircase count, the
 * quantity the lab's pixel images measure; never compare it with a length in µm).
 */
export function labelContactThresholdTexels(seededGrid: Grid, settings: LabProtocolSettings = LAB_PROTOCOL): number {
  return (settings.minContactPixels * seededGrid.width) / settings.referenceWidthPixels;
}
