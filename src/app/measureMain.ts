/**
 * "Measure a tissue" on the page (docs/app.md): its own module, beside main.ts, so that the
 * panel and the simulated sheet's wiring do not share state.
 */
import { mountMeasurePanel } from './panels/measurePanel';

mountMeasurePanel(document.querySelector<HTMLElement>('main')!);
