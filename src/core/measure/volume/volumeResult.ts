/**
 * The JSON shape of `tissue-sheet measure --volume` (docs/measure.md, "Measuring a volume"):
 * the layers mode's shape (MeasuredResult) with layers basal then apical, plus what a volume
 * adds (voxel size, cell volumes and heights, lateral neighbours).
 */
import type { MeasuredCellFields, MeasuredResultFields } from '../measuredResult';
import type { VolumeComparison } from './compareVolume';

export interface VolumeSurfaceRecord {
  readonly name: 'basal' | 'apical';
  /** Which background the surface faces. */
  readonly faces: 'outside' | 'lumen';
  /** Cells with at least one voxel face on this surface. */
  readonly cells: number;
  /** Sum of those cells' areas on it, µm². */
  readonly area: number;
  /** Shortest contact curve (µm) that makes two cells neighbours on this surface. */
  readonly minContact: number;
  /** Pairs of cells whose contact curve on this surface has any length (before min-contact). */
  readonly contactPairs: number;
}

interface VolumeInputs {
  readonly files: { readonly name: string; readonly bytes: number; readonly format: 'tiff'; readonly pages: number }[];
  readonly volume: {
    readonly width: number;
    readonly height: number;
    readonly depth: number;
    readonly bitsPerSample: 8 | 16 | 32;
    /** Distinct cell labels (without --lumen-label). */
    readonly labels: number;
    readonly voxels: number;
  };
  /** µm along width, height and between pages, and where it came from. */
  readonly voxelSize: { readonly x: number; readonly y: number; readonly z: number; readonly source: 'option' | 'imagej' | 'ome' };
  /** How the voxel size was read, e.g. "ImageJ unit=micron, XResolution 5 ...". */
  readonly voxelSizeDetail: string;
  /** basal, then apical. */
  readonly layers: VolumeSurfaceRecord[];
  readonly background: {
    readonly outsideVoxels: number;
    readonly lumenComponents: number;
    readonly lumenVoxels: number;
    readonly labelledLumenVoxels: number;
    /** Enclosed background components smaller than half the mean cell: ignored. */
    readonly pockets: number;
    readonly pocketVoxels: number;
    /** A lumen reaches a face of the volume: an open piece (a tube cut by the volume), not a closed shell. */
    readonly lumenReachesFaces: boolean;
  };
  readonly options: {
    readonly apical: 'lumen' | 'outside';
    readonly lumenLabel: number | null;
    /** --min-contact as given (µm), or null. */
    readonly minContact: number | null;
    readonly minContactSource: 'option' | 'default';
    readonly quartetFilter: boolean;
  };
}

export interface VolumeContactRecord {
  readonly label: number;
  /** The contact curve's length on the surface, µm (smoothed, not the voxel staircase). */
  readonly length: number;
  /** Sum of the voxel-edge lengths along the curve, µm (for reference; up to √3 too long). */
  readonly staircase: number;
  readonly edges: number;
  /** Connected pieces of the curve. */
  readonly pieces: number;
}

export interface LateralContactRecord {
  readonly label: number;
  /** Shared interface area, µm² (voxel faces weighted by the interface's mean normal). */
  readonly area: number;
  /** Voxel faces shared. */
  readonly faces: number;
}

export interface VolumeExclusion {
  /** Layers (0 basal, 1 apical) the cell does not reach. */
  readonly missingFrom: number[];
  /** Faces of the volume it has a voxel on: "first column", "last row", "first page", ... */
  readonly touchesFaces: string[];
  readonly reason: string;
}

/** Areas, sides, neighbours and contacts per layer: basal, apical (contacts: curves). */
export interface VolumeCellRecord extends MeasuredCellFields<VolumeContactRecord, VolumeExclusion> {
  /** Voxel count x voxel volume, µm³. */
  readonly volume: number;
  /** Distance between the cell's basal and apical surface centroids, µm (null without both). */
  readonly height: number | null;
  /** Area-weighted centroid (µm, x y z from the volume's corner) of its faces on each layer, null where it has none. */
  readonly centroids: ([number, number, number] | null)[];
  /** Cells sharing an interface of at least (the larger min-contact)² µm² anywhere in the volume. */
  readonly lateralNeighbours: number[];
  readonly lateralContacts: LateralContactRecord[];
}

export interface VolumeMeasuredResult extends MeasuredResultFields<VolumeInputs, VolumeCellRecord> {
  readonly exclusions: { readonly touchesFaces: number; readonly missing: number; readonly total: number };
  /** With the quartet filter: the quartets found and the exchanges it removed (labels). */
  readonly quartetFilter: {
    readonly quartets: number[][];
    readonly removed: { readonly labels: [number, number]; readonly layer: number }[];
  } | null;
  /** With --compare: the model of the same tissue (closed shells: on their own meshes; open pieces: the fitted tube), else null. */
  readonly comparison: VolumeComparison | null;
  readonly timings: {
    readonly readMs: number;
    readonly classifyMs: number;
    readonly contactsMs: number;
    readonly analysisMs: number;
    readonly totalMs: number;
  };
}
