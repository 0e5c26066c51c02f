/**
 * The page's headline over realizations (issue 26): after a result is on screen (realization 1),
 * the other seeds run in a worker of their own (view/realizations.ts) and the headline becomes
 * their mean with its 95 % CI. Combined headlines are kept by configuration and n, so a redraw
 * or going back to a configuration does not compute them again. The number of realizations is
 * part of the result on screen: the address carries it (`&realizations=N`) when it is not the
 * default, and a link with it sets the control. (Moved out of main.ts.)
 */
import type { Headline } from '../../core/analysis/headline';
import { checkRealizations, DEFAULT_REALIZATIONS } from '../../core/analysis/realizations';
import type { SheetOutput } from '../../run';
import { isAbort } from '../../view/pageRunner';
import { realizationsHeadline } from '../../view/realizations';
import type { ViewStack } from '../../view/stack';
import { renderHeadline } from './results';

const REALIZATIONS_PARAM = 'realizations';

export interface RealizationsPanelOptions {
  /** The realizations number box. */
  readonly input: HTMLInputElement;
  /** Where the headline is rendered. */
  readonly main: HTMLElement;
  /** The stack on screen. */
  readonly shown: () => ViewStack | null;
  /** Puts `stack` (the one on screen, with its headline over realizations) in its place. */
  readonly replace: (stack: ViewStack) => void;
  readonly onError: (message: string) => void;
  /** The box's value is valid again: its earlier error (`message`) goes. */
  readonly onValid: (message: string) => void;
  /** Realizations started or stopped (the page's cancel button follows). */
  readonly onBusy: () => void;
}

/** `href` with `&realizations=n`, or without the parameter when n is the default (5). */
function urlWithRealizations(href: string, n: number): string {
  const url = new URL(href);
  if (n === DEFAULT_REALIZATIONS) url.searchParams.delete(REALIZATIONS_PARAM);
  else url.searchParams.set(REALIZATIONS_PARAM, String(n));
  return url.toString();
}

/** `shown` with `headline` as its result's headline (the views and exports read the same stack). */
function withHeadline(shown: ViewStack, headline: Headline | null): ViewStack {
  return { ...shown, result: { ...shown.result, headline } };
}

/** Realization 1's own headline, from a headline over realizations (its counts are realization 1's). */
function drawnHeadline(h: Headline): Headline {
  if (h.realizations <= 1) return h;
  const value = h.realizationValues[0] ?? null;
  return { ...h, percentScutoids: value, realizations: 1, ci95: null, sd: null, realizationSeeds: h.realizationSeeds.slice(0, 1), realizationValues: [value] };
}

export class RealizationsPanel {
  private controller: AbortController | null = null;
  private readonly combined = new Map<string, Headline>();
  /**
   * The number of realizations of the result on screen (the last valid value of the box): the
   * headline is over it and the address carries it. An invalid value in the box changes nothing.
   */
  private n: number = DEFAULT_REALIZATIONS;
  /** The box's error on screen, if any (cleared once its value is valid). */
  private error: string | null = null;

  constructor(private readonly options: RealizationsPanelOptions) {
    const { input } = options;
    const fromLink = new URL(location.href).searchParams.get(REALIZATIONS_PARAM);
    if (fromLink !== null) {
      try {
        input.value = String(checkRealizations(fromLink, 'realizations (in the link)'));
      } catch (error) {
        // After the page's modules are set up (the form exists then).
        queueMicrotask(() => {
          this.error = (error as Error).message;
          options.onError(this.error);
        });
      }
    }
    const initial = Number(input.value);
    this.n = Number.isInteger(initial) && initial >= 1 && initial <= 100 ? initial : DEFAULT_REALIZATIONS;
    input.addEventListener('change', () => {
      // Validated first: an invalid value leaves the screen, and the address, as they are.
      const n = this.asked();
      if (n === null) return;
      this.n = n;
      this.syncParam();
      const stack = options.shown();
      if (!stack) return;
      const output = {
        result: { ...stack.result, headline: stack.result.headline ? drawnHeadline(stack.result.headline) : null },
        labelImages: stack.surfaces.map((s) => s.image),
      } as SheetOutput;
      void this.start(output);
    });
  }

  /**
   * An opened file's number of realizations (its headline's n), set in the control before the
   * file is shown (or its configuration run again); the address follows once it is on screen
   * (syncParam), as for a result run here. A value that is not one is ignored.
   */
  setFromFile(n: unknown): void {
    if (!(typeof n === 'number' && Number.isInteger(n) && n >= 1 && n <= 100)) return;
    this.n = n;
    this.options.input.value = String(n);
    this.options.input.removeAttribute('aria-invalid');
    this.clearOwnError();
  }

  /** Whether realizations are being computed. */
  get running(): boolean {
    return this.controller !== null;
  }

  private key(stack: ViewStack, n: number): string {
    return `${n}|${JSON.stringify(stack.result.config)}`;
  }

  /** The number of realizations asked for, or null (and the field marked) when it is not one. */
  private asked(): number | null {
    const { input } = this.options;
    try {
      const n = checkRealizations(input.value.trim().replace(',', '.'), 'Realizations');
      input.removeAttribute('aria-invalid');
      this.clearOwnError();
      return n;
    } catch (error) {
      input.setAttribute('aria-invalid', 'true');
      this.error = (error as Error).message;
      this.options.onError(this.error);
      return null;
    }
  }

  private clearOwnError(): void {
    if (this.error !== null) this.options.onValid(this.error);
    this.error = null;
  }

  /** The address carries the number of realizations of the result on screen when it is not the default. */
  syncParam(): void {
    const next = urlWithRealizations(location.href, this.n);
    if (next !== location.href) history.replaceState(null, '', next);
  }

  /**
   * A new result about to be shown: with the headline over realizations when it is already
   * known for its configuration and n, and whether it waits for realizations (marked on the page).
   */
  prepare(shown: ViewStack, opened: boolean): { stack: ViewStack; waiting: boolean; n: number } {
    const n = this.n;
    const known = n > 1 ? this.combined.get(this.key(shown, n)) : undefined;
    const stack = known ? withHeadline(shown, known) : shown;
    const waiting = !known && !opened && n > 1 && (stack.result.headline?.realizations ?? 1) <= 1;
    document.body.dataset.headline = waiting ? 'partial' : 'complete';
    return { stack, waiting, n };
  }

  stop(): void {
    this.controller?.abort();
    this.controller = null;
  }

  /** Computes the headline of the result on screen over the realizations asked for. */
  async start(output: SheetOutput): Promise<void> {
    this.stop();
    const { main, shown: current, replace, onBusy } = this.options;
    const shown = current();
    if (!shown) return;
    const n = this.n;
    const drawn = output.result.headline;
    const done = (headline: Headline | null) => {
      if (current() !== shown) return;
      const next = withHeadline(shown, headline);
      replace(next);
      renderHeadline(main, next, null);
      document.body.dataset.headline = 'complete';
    };
    if (n <= 1 || !drawn) {
      done(drawn);
      return;
    }
    const known = this.combined.get(this.key(shown, n));
    if (known) {
      done(known);
      return;
    }
    const controller = new AbortController();
    this.controller = controller;
    document.body.dataset.headline = 'partial';
    renderHeadline(main, shown, { state: 'running', done: 1, n });
    onBusy();
    try {
      const headline = await realizationsHeadline({
        output,
        n,
        signal: controller.signal,
        onProgress: (k, total) => current() === shown && renderHeadline(main, shown, { state: 'running', done: k, n: total }),
      });
      if (controller.signal.aborted) return;
      if (headline) {
        if (this.combined.size > 32) this.combined.clear();
        this.combined.set(this.key(shown, n), headline);
      }
      done(headline);
    } catch (error) {
      if (current() !== shown) return;
      const cancelled = isAbort(error) || controller.signal.aborted;
      renderHeadline(main, shown, { state: cancelled ? 'cancelled' : 'failed', n, message: (error as Error)?.message });
      document.body.dataset.headline = cancelled ? 'cancelled' : 'failed';
    } finally {
      if (this.controller === controller) this.controller = null;
      onBusy();
    }
  }
}
