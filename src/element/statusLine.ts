/**
 * The element's status line: what it is doing or why it failed, followed by its standing
 * warnings (unknown attributes, a fallback from the worker to the page), so a warning is still in
 * sight after the status that first said it has been replaced.
 */
import type { ComputeSite } from '../run';

/** What the status line writes on (an HTMLElement; a plain object in tests). */
export interface StatusElement {
  textContent: string | null;
  readonly classList: { toggle(token: string, force?: boolean): boolean };
}

export class StatusLine {
  private unknown: string[] = [];
  private fallback: string | null = null;
  /** The text shown last (without the warnings), for `refresh`. */
  private text: { text: string; error: boolean } | null = null;

  constructor(private readonly line: StatusElement) {}

  /** `text` with the warnings after it; `error` marks it as a failure. */
  show(text: string, error = false): void {
    this.text = { text, error };
    const warnings = [...this.unknown, ...(this.fallback ? [this.fallback] : [])];
    this.line.textContent = warnings.length ? `${text} — ${warnings.join('; ')}.` : text;
    this.line.classList.toggle('error', error);
  }

  /** The unknown-attribute warnings now (they replace the previous ones). */
  setUnknownAttributes(messages: readonly string[]): void {
    this.unknown = [...messages];
  }

  /** Writes the last text again with the warnings as they are now (an attribute changed since). */
  refresh(): void {
    if (this.text) this.show(this.text.text, this.text.error);
    else if (this.unknown.length) this.show('');
  }

  /**
   * After a run: the first time runs fell back from the worker to the page, the warning that
   * says so (kept on the line from then on); else null.
   */
  noteFallback(site: ComputeSite): string | null {
    if (this.fallback !== null || site.where !== 'page') return null;
    this.fallback = `computed on the page, not in a worker (${site.reason}): the page may pause during runs`;
    return this.fallback;
  }
}
