/**
 * The element's slider path (issue 27), as the app's drag: a change of `sheet.*` only
 * (surface-ratio, thickness) on the result shown, with the same inputs, reuses the worker's
 * converged seeded surface and gets draft pictures, so its result event follows in tens of
 * milliseconds; once the changes settle (FULL_PICTURES_DELAY_MS), the same result is fetched
 * again with its full pictures (the worker's cached seeded surface: the same numbers) and only
 * the 3D view is redrawn.
 */
import type { Config } from '../core/config';
import type { GrayImage } from '../core/density';
import type { MeshFile, SheetOutput } from '../run';
import { FULL_PICTURES_DELAY_MS, runInPage, sheetOnlyChange, type LatestRunner } from '../view/pageRunner';

/** The configuration and inputs of the result on screen. */
interface Shown {
  readonly config: Config;
  readonly image: GrayImage | null;
  readonly mesh: MeshFile | null;
  readonly output: SheetOutput;
}

export class LivePath {
  private shown: Shown | null = null;

  /** `draw`: shows the full pictures of the result on screen (the element's 3D view). */
  constructor(
    private readonly runner: LatestRunner,
    private readonly draw: (full: SheetOutput) => void,
  ) {}

  /** Whether a run of `config` on these inputs changes only `sheet.*` of the result on screen. */
  applies(config: Config, image: GrayImage | null, mesh: MeshFile | null): boolean {
    return this.shown !== null && this.shown.image === image && this.shown.mesh === mesh && sheetOnlyChange(this.shown.config, config);
  }

  /** The result now on screen; after a live run its full pictures follow once changes settle. */
  show(shown: Shown, live: boolean): void {
    this.shown = shown;
    if (live) this.runner.debounced(FULL_PICTURES_DELAY_MS, () => void this.redrawInFull(shown.output));
  }

  private async redrawInFull(output: SheetOutput): Promise<void> {
    const shown = this.shown;
    if (shown?.output !== output || this.runner.running) return;
    try {
      const full = await runInPage({ config: output.result.config, densityImage: shown.image ?? undefined, meshFile: shown.mesh });
      if (this.shown?.output !== output || this.runner.running) return;
      this.draw(full);
    } catch {
      // The draft pictures stay: they show the same result.
    }
  }
}
