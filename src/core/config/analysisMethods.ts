/**
 * Which engine runs a config and which adjacency methods its run reports: the one description
 * that the engine policy (src/run/enginePolicy.ts), the stack (src/run/stack.ts, which computes
 * the analyses) and the sweep's columns (src/core/sweep/columns.ts, which fixes runs.csv's header
 * before the first run) all read, so what a run reports and what a sweep expects cannot drift
 * apart again.
 *
 * Every surface has an exact method: the Delaunay of the unrolled sites on planes and tubes, the
 * restricted Voronoi diagram on spheres, ellipsoids and meshes.
 */
import { surfaceLayout } from './surfaceLayout';
import type { Config } from './types';

export const ADJACENCY_METHODS = ['labels', 'exact'] as const;
/** `labels`: adjacent texels of the label images; `exact`: the exact Voronoi diagram. */
export type AdjacencyMethod = (typeof ADJACENCY_METHODS)[number];

/** The engines: jump flood and centroid passes on the GPU, or Lloyd on the exact diagram on the CPU. */
export type EngineName = 'gpu' | 'exact';

/** What the engine policy needs to know of the renderer. */
export interface RendererTraits {
  readonly softwareRenderer: boolean;
}

/**
 * The engine a config runs on: planes and tubes with engine "exact", or "auto" on a software
 * renderer when the labels method is not asked for (there the "GPU" is the CPU, and the exact
 * computation costs a fraction of a jump flood); the GPU otherwise. Closed surfaces always run
 * on the GPU (their exact method is an analysis, not a Lloyd engine).
 */
export function engineNameFor(config: Config, renderer: RendererTraits): EngineName {
  if (!surfaceLayout(config).exactEngine) return 'gpu';
  if (config.engine === 'exact') return 'exact';
  if (config.engine === 'auto' && renderer.softwareRenderer && config.sheet.adjacency !== 'labels') return 'exact';
  return 'gpu';
}

/**
 * The adjacency methods a run of `config` on `engine` reports, in the order of the result's
 * `analyses`: the exact engine makes no label images, so it reports "exact" only; the GPU
 * engine reports what sheet.adjacency asks for ("both": labels, then exact).
 */
export function analysisMethods(config: Config, engine: EngineName): AdjacencyMethod[] {
  if (engine === 'exact') return ['exact'];
  const { adjacency } = config.sheet;
  return ADJACENCY_METHODS.filter((method) => adjacency === 'both' || adjacency === method);
}

/** The methods a run of `config` reports on a renderer with these traits. */
export function methodsOnRenderer(config: Config, renderer: RendererTraits): AdjacencyMethod[] {
  return analysisMethods(config, engineNameFor(config, renderer));
}

/**
 * The method of a result's headline (the number the page, the element and the CLI show): the
 * exact method wherever it ran (no pixels, true contact lengths), else the labels method.
 */
export function headlineMethod(methods: readonly AdjacencyMethod[]): AdjacencyMethod | null {
  return methods.includes('exact') ? 'exact' : methods.includes('labels') ? 'labels' : null;
}
