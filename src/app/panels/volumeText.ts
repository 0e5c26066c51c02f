/**
 * The words of "Measure a volume" (volumePanel.ts): its form and results markup, the core's
 * messages reworded for the page's fields, and the one-paragraph description of a measured volume.
 */
import type { VolumeMeasuredResult } from '../../core/measure';

export const VOLUME_OPTIONS = `
  <fieldset class="measure-options volume-options">
    <legend>One 3D TIFF</legend>
    <label title="A 3D segmentation (one label per cell through the depth) or a stack of 2D layers (one page per depth)">is
      <select id="measure-tiff-as"><option value="volume" selected>a label volume (3D segmentation)</option><option value="layers">layers (one page per depth, basal first)</option></select></label>
    <span title="Voxel edge along the image width, height, and between pages, in micrometres; empty: from the TIFF metadata (ImageJ or OME)">Voxel size (µm)
      <label>X <input id="volume-voxel-x" type="number" min="0" step="any" placeholder="from the file" /></label>
      <label>Y <input id="volume-voxel-y" type="number" min="0" step="any" placeholder="from the file" /></label>
      <label>Z <input id="volume-voxel-z" type="number" min="0" step="any" placeholder="from the file" /></label></span>
    <label title="Biologists' convention: the apical side faces the lumen">Apical side faces
      <select id="volume-apical"><option value="lumen" selected>the lumen</option><option value="outside">the outside</option></select></label>
    <label title="Voxels with this label are lumen, not a cell">Lumen label <input id="volume-lumen-label" type="number" min="1" step="1" placeholder="none" /></label>
    <label title="Keep a scutoid only where an intercalating quartet confirms it (the lab's filter)"><input id="volume-quartets" type="checkbox" /> quartet filter</label>
  </fieldset>`;

export const VOLUME_RESULTS = `
  <div id="volume-results" hidden>
    <p class="headline"><output id="volume-measured-percent">–</output> scutoids measured;
      model of the same geometry <output id="volume-model-percent">–</output></p>
    <p id="volume-info" class="small"></p>
    <div class="measure-options"><label title="The measured tissue, the model of the same geometry (its first realization), or both: the tissue above, the model below, one camera">Show
      <select id="volume-layout" disabled><option value="both">tissue and model (model below)</option><option value="tissue" selected>tissue</option><option value="model">model</option></select></label>
      <span id="volume-drawing-note" class="small"></span></div>
    <div id="volume-view" class="volume-view"></div>
    <p class="small">Left: basal surface; middle: apical surface (one camera for all views: drag to turn them together); right: the picked cell's 3D shape (for a model cell, its own basal and apical faces). Below the tissue, the model of the same geometry (first realization of the best Voronoi k) with the same legend. Legend as the model's views: cells coloured by their sides on that surface, scutoids striped, cells left out faded, the picked cell white; while a cell is picked, cells that are not its neighbours on that surface are darkened.</p>
    <div id="volume-cell" class="small" aria-live="polite"></div>
    <div id="volume-model-cell" class="small" aria-live="polite"></div>
    <div id="volume-summary-box" class="table-box"></div>
    <p id="volume-model" class="small"></p>
    <div class="measure-options">
      <button type="button" id="volume-json" title="The measured volume with its model, as tissue-sheet measure --volume --compare writes it">Volume JSON</button>
      <button type="button" id="volume-cells-csv" title="One row per cell: valid, scutoid, sides, areas, neighbours on both surfaces, volume, height, lateral neighbours">Per-cell CSV</button>
      <button type="button" id="volume-figure-svg" title="Measured and model polygon distributions with the statistics, at the width chosen under the exports">Figure SVG</button>
      <button type="button" id="volume-figure-png" title="The same figure as PNG, at the DPI and width chosen under the exports">Figure PNG</button>
      <button type="button" id="volume-view-png" title="The 3D view as shown (basal, apical, picked cell; the tissue, the model or both, as chosen under Show), with its provenance in the PNG's text">3D view PNG</button>
    </div>
  </div>`;

/** The core's messages name the CLI's options; the page names its fields. */
export function volumeWords(message: string): string {
  return message
    .replace(/give --voxel-size X,Y,Z in µm/g, 'type the voxel size (µm) in the X, Y and Z fields above')
    .replace(/--voxel-size( [\d.,]+)?/g, 'the voxel size fields')
    .replace(/--lumen-label N/g, 'a lumen label (the field above)')
    .replace(/--lumen-label/g, 'the lumen label field')
    .replace(/--min-contact/g, 'the min contact field')
    .replace(/--apical outside/g, 'apical side faces the outside');
}

/** What was measured, in one paragraph: the file, its cells, the voxel size and its source, each surface. */
export function describeVolume(result: VolumeMeasuredResult): string {
  const s = result.analyses[0].summary;
  const { volume: d, voxelSize: v, layers, background: b } = result.inputs;
  const warnings = result.warnings.length ? ` Warnings: ${result.warnings.map(volumeWords).join('; ')}.` : '';
  return (
    `${result.inputs.files[0].name}: ${d.width} x ${d.height} x ${d.depth} voxels, ${d.bitsPerSample}-bit, ${d.labels} cells, ${s.validCells} valid ` +
    `(${result.exclusions.touchesFaces} touch a face of the volume, ${result.exclusions.missing} miss the lumen or the outside); ` +
    `voxel ${v.x} x ${v.y} x ${v.z} µm (${v.source === 'option' ? 'typed in the page' : `from the ${v.source === 'ome' ? 'OME-XML' : 'ImageJ'} metadata`}); ` +
    `${b.lumenReachesFaces ? 'an open piece (the lumen reaches a face of the volume)' : 'a closed shell'}; ` +
    layers.map((l) => `${l.name}: faces the ${l.faces}, ${l.cells} cells, ${l.area.toFixed(0)} µm², min contact ${l.minContact.toPrecision(3)} µm`).join('; ') +
    `.${warnings}`
  );
}
