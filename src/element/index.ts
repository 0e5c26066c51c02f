/**
 * The `<tissue-sheet>` web component. Importing this module defines the element.
 *
 *   <script type="module" src="tissue-sheet.js"></script>
 *   <tissue-sheet cells="150" surface-ratio="2"></tissue-sheet>
 */
import { TissueSheetElement } from './TissueSheetElement';

export { TissueSheetElement } from './TissueSheetElement';
export { ATTRIBUTES } from './attributes';
export type {
  TissueSheetCellHoverDetail,
  TissueSheetErrorDetail,
  TissueSheetEventMap,
  TissueSheetProgressDetail,
  TissueSheetResultDetail,
  TissueSheetWaitingDetail,
  TissueSheetWarningDetail,
} from './events';
export type { Config, PlanarConfig, ClosedConfig, ConfigInput } from '../core/config';
export type { MeshFile } from '../run/closedMesh';
export type { GrayImage } from '../core/density';
export type { SheetResult, AnalysisRecord, CellRecord, CellStatisticsRecord, ClosedSurfaceRecord, SurfaceRecord } from '../run/result';

if (typeof customElements !== 'undefined' && !customElements.get('tissue-sheet')) {
  customElements.define('tissue-sheet', TissueSheetElement);
}

declare global {
  interface HTMLElementTagNameMap {
    'tissue-sheet': TissueSheetElement;
  }
}
