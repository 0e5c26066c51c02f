/**
 * Chart figures as files: the sweep chart and the Flintstones fit (and the measured-vs-model
 * comparison) as SVG and PNG at the DPI and width chosen beside the figure buttons (#figure-dpi,
 * #figure-width), each with its provenance: version, the configuration or sweep spec, seed,
 * engine and method, in the SVG's <desc>/<metadata> and the PNG's tEXt chunks.
 */
import { version } from '../../version';
import { chartSvg, type ChartSpec } from '../model/chartSvg';
import { figureSize, svgPng, type FigureOptions } from '../view/figure';
import { download } from './exports';

/** The DPI and width (mm) chosen beside the figure buttons (300 dpi, 180 mm when absent). */
function chosenFigureOptions(): FigureOptions {
  const dpi = Number(document.querySelector<HTMLSelectElement>('#figure-dpi')?.value ?? 300);
  const widthMm = Number(document.querySelector<HTMLInputElement>('#figure-width')?.value ?? 180);
  figureSize({ dpi, widthMm }, 1); // refuses a DPI or width out of range, in words
  return { dpi, widthMm };
}

export interface ChartProvenance {
  /** What the figure is ("tissue-sheet sweep chart"). */
  what: string;
  engine: string;
  method: string;
  seed: number | string;
  /** The configuration or sweep spec that reproduces it. */
  config: unknown;
}

function provenanceOf(p: ChartProvenance): string[] {
  return [
    `${p.what}, written by tissue-sheet ${version}`,
    `engine: ${p.engine}`,
    `method: ${p.method}`,
    `seed ${p.seed}; configuration (rerun it to reproduce this figure): ${JSON.stringify(p.config)}`,
  ];
}

/** The chart `figure` as an SVG or PNG download named `name` (no extension). */
export async function downloadChart(
  kind: 'svg' | 'png',
  name: string,
  figure: Omit<ChartSpec, 'provenance' | 'metadata' | 'widthMm'> | null,
  provenance: ChartProvenance,
): Promise<void> {
  if (!figure) throw new Error('There is no chart to save yet: run a sweep first.');
  const options = chosenFigureOptions();
  const lines = provenanceOf(provenance);
  const svg = chartSvg({ ...figure, widthMm: options.widthMm, provenance: lines, metadata: { software: { name: 'tissue-sheet', version }, ...provenance } });
  if (kind === 'svg') {
    download(`${name}.svg`, svg, 'image/svg+xml');
    return;
  }
  const png = await svgPng(svg, options, [
    ['Software', `tissue-sheet ${version}`],
    ['Description', [...lines, `${options.dpi} dpi, ${options.widthMm} mm wide`].join('\n')],
    ['tissue-sheet:version', version],
    ['tissue-sheet:seed', String(provenance.seed)],
    ['tissue-sheet:engine', provenance.engine],
    ['tissue-sheet:method', provenance.method],
    ['tissue-sheet:config', JSON.stringify(provenance.config)],
  ]);
  download(`${name}-${options.dpi}dpi.png`, new Blob([png as BlobPart], { type: 'image/png' }));
}
