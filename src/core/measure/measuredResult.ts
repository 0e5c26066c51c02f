import type { AnalysisRecord, CellStatisticsRecord } from '../analysis/record';
/**
 * The JSON shape of `tissue-sheet measure` (docs/measure.md, "Result"). `analyses[0]` has the
 * shape of a simulated result's AnalysisRecord (src/run/result.ts; a test checks that the types
 * agree), so charts and exports read measured and simulated statistics alike.
 */
import type { PixelSizeSource } from './labelImage';
import type { ModelComparison } from './compare';

interface MeasuredFileRecord {
  readonly name: string;
  readonly bytes: number;
  readonly format: 'png' | 'tiff';
  readonly pages: number;
}

export interface MeasuredLayerRecord {
  /** "basal", "layer k", "apical". */
  readonly name: string;
  readonly file: string;
  /** Page in the file, 0-based. */
  readonly page: number;
  readonly width: number;
  readonly height: number;
  readonly bitsPerSample: 8 | 16;
  /** Distinct non-zero labels on this layer. */
  readonly labels: number;
  readonly labelledPixels: number;
  /** Pairs of labels sharing at least one pixel edge (before min-contact). */
  readonly contactPairs: number;
}

interface MeasuredInputs {
  readonly files: MeasuredFileRecord[];
  readonly layers: MeasuredLayerRecord[];
  readonly pixelSize: { readonly value: number; readonly source: PixelSizeSource; readonly file: string | null; readonly detail: string };
  readonly layerSpacing: number | null;
  readonly options: {
    readonly periodicX: boolean;
    /** --min-contact as given (µm), or null. */
    readonly minContact: number | null;
    readonly minContactSource: 'option' | 'default';
  };
}

/** The per-cell statistics of analyses[0].cells (a simulated result's), with the original label. */
interface MeasuredCellStatistics extends CellStatisticsRecord {
  readonly label: number;
}

/** A simulated result's AnalysisRecord (labels method, default protocol), cells with their labels. */
export interface MeasuredAnalysis extends AnalysisRecord {
  readonly method: 'labels';
  readonly cells: MeasuredCellStatistics[];
}

export interface ContactRecord {
  readonly label: number;
  /** 4-connected pixel edges shared. */
  readonly edges: number;
  /** edges x pixel size, µm. */
  readonly length: number;
}

export interface BorderTouch {
  readonly layer: number;
  readonly sides: ('left' | 'right' | 'top' | 'bottom')[];
}

export interface CellExclusion {
  /** Layers (0-based) where the label has no pixel. */
  readonly missingFrom: number[];
  readonly touchesBorder: BorderTouch[];
  /** The same in words. */
  readonly reason: string;
}

/** A measured cell's record in both modes (layers; a volume's basal and apical surfaces). */
export interface MeasuredCellFields<Contact, Exclusion> {
  readonly id: number;
  readonly label: number;
  readonly valid: boolean;
  readonly scutoid: boolean;
  /** µm² per layer (0 where missing). */
  readonly areas: number[];
  readonly sides: number[];
  /** Labels of the neighbours per layer (contacts >= min-contact), ascending. */
  readonly neighbours: number[][];
  /** Every contact per layer, also those below min-contact. */
  readonly contacts: Contact[][];
  readonly won: number;
  readonly lost: number;
  readonly transitions: number;
  readonly neighbours3D: number;
  readonly exclusion: Exclusion | null;
}

export type MeasuredCellRecord = MeasuredCellFields<ContactRecord, CellExclusion>;

/** What a measured result holds in both modes. */
export interface MeasuredResultFields<Inputs, Cell> {
  readonly software: { readonly name: 'tissue-sheet'; readonly version: string };
  readonly kind: 'measured';
  readonly inputs: Inputs;
  readonly analyses: MeasuredAnalysis[];
  readonly cells: Cell[];
  readonly warnings: string[];
}

export interface MeasuredResult extends MeasuredResultFields<MeasuredInputs, MeasuredCellRecord> {
  readonly exclusions: { readonly touchesBorder: number; readonly missing: number; readonly total: number };
  /** Apical over basal size around the tube. */
  readonly surfaceRatio: { readonly value: number; readonly source: 'widths' | 'areas' | 'option' };
  readonly comparison: ModelComparison | null;
  readonly timings: { readonly readMs: number; readonly contactsMs: number; readonly analysisMs: number; readonly totalMs: number };
}
