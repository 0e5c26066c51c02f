/**
 * The compute budget of runs in a page (the app and `<tissue-sheet>`): a configuration from a
 * link or an attribute is untrusted input, so its work and memory are estimated from the
 * configuration alone (core/config/limits.ts, shared with the CLI) and refused before anything
 * is allocated. A page cannot raise the budget: the CLI and the library can (`--allow-large`).
 */
import type { Config } from '../core/config';
import { checkLimits, type ComputeBudget, type RunEstimate } from '../core/config/limits';

/**
 * 2^30 texel-floods: the published tube (512 x 4096 texels) for 100 Lloyd iterations with room
 * to spare; a few minutes at most on a software GPU, well under a second per iteration on a real one.
 */
export const PAGE_MAX_WORK = 2 ** 30;
/** Estimated bytes at most: what a browser tab can hold beside the page. */
export const PAGE_MAX_BYTES = 1.5 * 2 ** 30;

const RAISE_HINT = 'run it with the command-line tool (tissue-sheet run --allow-large), where the limit can be raised';

function pageBudget(maxTextureSize: number): ComputeBudget {
  return { maxTextureSize, maxWork: PAGE_MAX_WORK, maxBytes: PAGE_MAX_BYTES };
}

/** Throws a ConfigError naming the field, the estimate and the limit when `config` is over budget. */
export function checkPageBudget(config: Config, maxTextureSize: number): RunEstimate {
  return checkLimits(config, pageBudget(maxTextureSize), RAISE_HINT);
}
