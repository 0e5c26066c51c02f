/**
 * A refusal in a biologist's words: what to change, in µm and cells; the engine's own message
 * (texels, resolution, GPU, budget) goes to a details line. The core's messages stay as they are
 * (the CLI and the element print them; tests match them); the page explains the ones that speak
 * of the engine.
 */
import { ConfigError, unrolledDomain, validateConfig, type Config, type SurfaceConfig } from '../../core/config';
import { layoutOfKind } from '../../core/config/surfaceLayout';
import { checkTexelsPerSide } from '../../core/config/limits';

export interface Refusal {
  /** What is wrong and what to change, without engine words. */
  readonly message: string;
  /** The engine's message, when the main line replaced it; null when the message says it all. */
  readonly details: string | null;
}

const ENGINE_WORDS = /texel|resolution|GPU|texture|flood|budget|render/i;
const um = (v: number) => `${Number(v.toPrecision(4))} µm`;

/** Field paths in the page's words. */
const FIELD_WORDS: Record<string, string> = {
  'sheet.thickness': 'Thickness',
  'sheet.surfaceRatio': 'Surface ratio',
  cells: 'Cells',
  resolution: 'Resolution (Advanced)',
  'lloyd.maxIterations': 'Lloyd iterations',
  'surface.radius': 'Radius',
  'surface.length': 'Length',
  'surface.width': 'Width',
  'surface.height': 'Height',
};

/** Whether `config` with `sheet` in place of its own passes the other surface's size check. */
function fits(config: Config, sheet: Record<string, unknown>): boolean {
  try {
    checkTexelsPerSide(validateConfig({ ...config, sheet: { ...config.sheet, ...sheet } }));
    return true;
  } catch {
    return false;
  }
}

/** The largest value in [0, hi] for which `ok` holds (bisection, 0.1 % of hi), or null. */
function largest(hi: number, ok: (v: number) => boolean): number | null {
  if (!ok(0)) return null;
  let a = 0;
  let b = hi;
  for (let k = 0; k < 40 && b - a > hi * 1e-3; k++) {
    const mid = (a + b) / 2;
    if (ok(mid)) a = mid;
    else b = mid;
  }
  return a;
}

/**
 * `error` (from validation, feasibility or the page's budget) for `config` (null when the
 * configuration itself could not be read), in words.
 */
export function explainRefusal(error: unknown, config: Config | null): Refusal {
  const text = error instanceof Error ? error.message : String(error);
  if (!ENGINE_WORDS.test(text)) return { message: text, details: null };
  const field = error instanceof ConfigError ? error.field : '';
  const surface = config?.surface;
  if (config && surface?.kind === 'tube' && (field === 'sheet.thickness' || field === 'sheet.surfaceRatio') && config.sheet.direction === 'inward') {
    if (field === 'sheet.thickness') {
      const t = config.sheet.thickness;
      const max = largest(t, (v) => fits(config, { thickness: Math.floor(v * 10) / 10 }));
      const best = max === null ? null : Math.floor(max * 10) / 10;
      return {
        message:
          `Thickness ${um(t)} inward leaves the inner surface of this tube (radius ${um(surface.radius)}) a radius of only ${um(Math.max(0, surface.radius - t))}: ` +
          `too small to draw its cells. Use a thickness of at most ${best === null ? 'a smaller value' : um(best)}, or make the tube wider (radius).`,
        details: text,
      };
    }
    const s = config.sheet.surfaceRatio ?? 1;
    return {
      message: `Surface ratio ${s} inward leaves the inner surface of this tube a radius of only ${um(surface.radius / s)}: too small to draw its cells. Use a smaller surface ratio, or make the tube wider (radius).`,
      details: text,
    };
  }
  if (config && (field === 'sheet.thickness' || field === 'sheet.surfaceRatio')) {
    return {
      message: `${FIELD_WORDS[field]}: the other surface would be too small to draw its cells. Use a smaller ${field === 'sheet.thickness' ? 'thickness' : 'surface ratio'}, or a larger surface.`,
      details: text,
    };
  }
  if (config && field === 'cells' && /texels/.test(text)) {
    const m = /has (\d+)/.exec(text);
    const fit = m ? Math.floor(Number(m[1]) / 16) : null;
    return {
      message: `${config.cells} cells are too many for this surface at this level of detail${fit ? `: at most ${fit} cells fit` : ''}. Use fewer cells, a larger surface, or raise the resolution under Advanced.`,
      details: text,
    };
  }
  if (config && field === 'resolution' && /short side/.test(text) && surface && layoutOfKind(surface.kind).aspectSetsShortSide) {
    const { lengthX: x, lengthY: y } = unrolledDomain(surface as SurfaceConfig);
    return {
      message: `This surface is too long and narrow to draw its cells (${um(x)} around or across, ${um(y)} along): make it shorter or wider, or raise the resolution under Advanced.`,
      details: text,
    };
  }
  if (/budget|texel-floods|GiB|memory/i.test(text)) {
    return {
      message: `This sheet is too large to compute in the page (${config ? `${config.cells} cells, ${config.lloyd.maxIterations} Lloyd iterations` : 'its size'}): use fewer cells, fewer Lloyd iterations or a lower resolution (Advanced), or run it with the command line.`,
      details: text,
    };
  }
  const words = FIELD_WORDS[field] ?? field;
  return {
    message: `${words ? `${words}: ` : ''}this value cannot be computed (see the details). Change it, or the resolution under Advanced.`,
    details: text,
  };
}

/** The seeded surface's area in µm² where the configuration alone gives it (null for meshes). */
function surfaceArea(config: Config): number | null {
  const s = config.surface;
  switch (s.kind) {
    case 'tube':
      return 2 * Math.PI * s.radius * s.length;
    case 'plane':
      return s.width * s.height;
    case 'sphere':
      return 4 * Math.PI * s.radius ** 2;
    case 'ellipsoid': {
      // Knud Thomsen's approximation (within 1.1 %).
      const p = 1.6075;
      return 4 * Math.PI * (((s.a * s.b) ** p + (s.a * s.c) ** p + (s.b * s.c) ** p) / 3) ** (1 / p);
    }
    default:
      return null;
  }
}

/**
 * A word when the cells would be smaller than any real cell (under 1 µm across): e.g. 100,000
 * cells on a 25 µm sphere are 0.28 µm across. `area` is the surface's (µm²) when known from a
 * result (meshes); null when the size is plausible.
 */
export function cellSizeNote(config: Config, area: number | null = surfaceArea(config)): string | null {
  if (area === null || !(area > 0)) return null;
  const diameter = Math.sqrt(area / config.cells);
  if (diameter >= 1) return null;
  return `Note: ${config.cells} cells on ${Number(area.toPrecision(3))} µm² are about ${diameter.toPrecision(2)} µm across, far smaller than an epithelial cell (a few µm or more): use fewer cells or a larger surface.`;
}
