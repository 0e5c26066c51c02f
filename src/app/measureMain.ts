/**
 * "Measure a tissue" on the page (docs/app.md): its own module, beside main.ts, so that the
 * panel and the simulated sheet's wiring do not share state; the measured tissue is kept in the
 * project file through its own section (measureProjectSection.ts).
 */
import { mountMeasurePanel } from './panels/measurePanel';
import { registerMeasuredSection } from './panels/measureProjectSection';

const panel = mountMeasurePanel(document.querySelector<HTMLElement>('main')!);
registerMeasuredSection(panel, document.querySelector<HTMLElement>('#measure')!);
