/** The element's events and their typed `detail`. */
import type { SheetResult } from '../run';

export interface TissueSheetProgressDetail {
  /** 1-based Lloyd iteration just finished. */
  iteration: number;
  maxIterations: number;
  /** CVT energy before the iteration's move, µm⁴. */
  energy: number;
  /** Largest site displacement of the iteration, µm. */
  maxDisplacement: number;
}

export interface TissueSheetResultDetail {
  /** The documented result JSON (the same document `tissue-sheet run` writes). */
  result: SheetResult;
  /** % scutoids of the labels analysis (the exact one when labels was not computed). */
  percentScutoids: number;
}

export interface TissueSheetErrorDetail {
  /** One line, in words: what went wrong and what to change. */
  message: string;
  /** "ConfigError", "GpuCapabilityError", or another error's name. */
  name: string;
  /** The config field at fault, for a ConfigError. */
  field?: string;
}

export interface TissueSheetEventMap {
  progress: CustomEvent<TissueSheetProgressDetail>;
  result: CustomEvent<TissueSheetResultDetail>;
  error: CustomEvent<TissueSheetErrorDetail>;
}
