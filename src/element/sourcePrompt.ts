/**
 * The element's question before loading a source from another origin (its `src` attribute, a
 * config's `density.src`): "this element asks to load PATH from HOST", and a button. Nothing is
 * requested from that origin before the click (view/sources.ts keeps the approval).
 */
import { approveSource, sourceQuestion, type ForeignSource } from '../view/sources';

export function askToLoad(shadow: ShadowRoot, pending: ForeignSource[], then: () => void): void {
  const box = shadow.querySelector<HTMLElement>('.ask')!;
  const [source] = pending;
  box.querySelector('p')!.textContent = sourceQuestion(source, 'This element');
  const button = box.querySelector('button')!;
  button.textContent = `Load ${source.path} from ${source.host}`;
  box.hidden = false;
  button.onclick = () => {
    box.hidden = true;
    approveSource(source);
    then();
  };
}
