/**
 * Messages that wait for the user: the link alert (a configuration from the address that cannot
 * be run: invalid, over the page's budget) stays until dismissed, unlike run errors, which the
 * next run clears; the source question ("this link asks to load PATH from HOST") loads a foreign
 * source only when its button is clicked.
 */
import { approveSource, sourceQuestion, type ForeignSource } from '../../view/sources';

export class LinkAlert {
  private readonly text: HTMLElement;

  constructor(private readonly root: HTMLElement) {
    this.text = root.querySelector<HTMLElement>('.message')!;
    root.querySelector<HTMLButtonElement>('button')!.addEventListener('click', () => this.dismiss());
  }

  show(message: string): void {
    this.text.textContent = message;
    this.root.hidden = false;
  }

  dismiss(): void {
    this.root.hidden = true;
    this.text.textContent = '';
  }
}

export class SourceQuestion {
  private readonly text: HTMLElement;
  private readonly load: HTMLButtonElement;
  private readonly cancel: HTMLButtonElement;
  private onLoad: (() => void) | null = null;

  constructor(private readonly root: HTMLElement) {
    this.text = root.querySelector<HTMLElement>('.message')!;
    this.load = root.querySelector<HTMLButtonElement>('[data-source="load"]')!;
    this.cancel = root.querySelector<HTMLButtonElement>('[data-source="cancel"]')!;
    this.load.addEventListener('click', () => {
      const next = this.onLoad;
      this.close();
      next?.();
    });
    this.cancel.addEventListener('click', () => this.close());
  }

  /** Asks about the first of `sources`; `then` runs after the click (and asks about the next). */
  ask(sources: ForeignSource[], who: string, then: () => void): void {
    const [source] = sources;
    this.text.textContent = sourceQuestion(source, who);
    this.load.textContent = `Load ${source.path} from ${source.host}`;
    this.onLoad = () => {
      approveSource(source);
      then();
    };
    this.root.hidden = false;
    this.load.focus();
  }

  close(): void {
    this.root.hidden = true;
    this.onLoad = null;
  }
}
