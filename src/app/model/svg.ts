/**
 * The unrolled view as SVG: every surface of a plane or tube side by side at its true
 * proportions (user units = µm), each cell its exact polygon (cellPolygons.ts) filled with its
 * side colour, border cells faded, scutoids hatched, with captions, a legend, a scale bar and the
 * provenance in <metadata>/<desc>. A tube's surface is periodic around x: polygons unwrapped
 * past the seam are drawn again one circumference over and clipped to the strip. Every polygon
 * carries data-cell, data-surface, data-sides, data-scutoid and data-valid, so a reader (and the
 * tests) can take the figure back to the numbers. Closed surfaces cannot be unrolled: refused.
 * The SVG is printed at the chosen width (mm, default 180); its viewBox stays in µm, so the
 * desc says how many µm one printed mm is. Under the surfaces: the scale bar, the headline's
 * numbers (mean % with its CI and n, method, Voronoi k), then the legend (svgFigure.ts: items
 * never overlap; the border-cell swatch is drawn on the surfaces' dark ground, as the cells are).
 */
import { SIDE_COLORS, SIDE_LABELS, sideColorIndex } from '../../view/sideColors';
import type { ViewStack } from '../../view/stack';
import { surfacePolygons } from '../../view/cellPolygons';
import { provenanceLines } from './cellRows';
import { niceScaleLength } from './scaleBar';
import { escapeXml, legendSvg, num, svgDocument, type LegendItem } from './svgFigure';

const GAP_FRACTION = 0.06;

export function unrolledSvg(stack: ViewStack, options: { widthMm?: number } = {}): string {
  if (stack.closed) throw new Error('SVG of the unrolled view: a closed surface cannot be unrolled; export the cells as VTK or PLY instead.');
  const surfaces = stack.surfaces;
  const widths = surfaces.map((s) => s.image.grid.width * s.image.grid.texelX);
  const heights = surfaces.map((s) => s.image.grid.height * s.image.grid.texelY);
  const tallest = Math.max(...heights);
  const gap = GAP_FRACTION * Math.max(...widths);
  const font = tallest / 40;
  const top = 2 * font;
  const plotBottom = top + tallest;
  let x = 0;
  const groups: string[] = [];
  surfaces.forEach((surface, k) => {
    const { grid } = surface.image;
    const w = widths[k];
    const h = heights[k];
    const clip = `clip-${k}`;
    const copies = grid.periodicX ? [-w, 0, w] : [0];
    const polys: string[] = [];
    for (const cell of surfacePolygons(surface).cells) {
      const p = cell.polygon;
      if (p.length < 6) continue;
      const id = cell.id;
      const color = SIDE_COLORS[sideColorIndex(surface.sides[id] ?? 0)];
      const faded = !stack.valid[id];
      const points = (shift: number) =>
        Array.from({ length: p.length / 2 }, (_, j) => `${num(p[2 * j] * grid.texelX + shift)},${num(h - p[2 * j + 1] * grid.texelY)}`).join(' ');
      for (const shift of copies) {
        const attrs = `data-cell="${id}" data-surface="${surface.index}" data-sides="${surface.sides[id]}" data-scutoid="${stack.scutoid[id]}" data-valid="${stack.valid[id]}"${shift !== 0 ? ' data-copy="1"' : ''}`;
        polys.push(`<polygon ${attrs} points="${points(shift)}" fill="${color}"${faded ? ' fill-opacity="0.35"' : ''}/>`);
        if (stack.scutoid[id]) polys.push(`<polygon points="${points(shift)}" fill="url(#hatch)" pointer-events="none"/>`);
      }
    }
    const offset = surface.offset !== 0 ? `, ${surface.offset.toFixed(1)} µm` : '';
    const ratio = surface.ratio !== 1 ? `, ratio ${surface.ratio.toFixed(2)}` : '';
    groups.push(
      `<g id="surface-${k}" data-name="${escapeXml(surface.name)}" transform="translate(${num(x)} ${num(top + tallest - h)})">` +
        `<clipPath id="${clip}"><rect width="${num(w)}" height="${num(h)}"/></clipPath>` +
        `<rect width="${num(w)}" height="${num(h)}" fill="#282828"/>` +
        `<g clip-path="url(#${clip})" stroke="#1a1a1a" stroke-width="${num(font / 12)}" stroke-linejoin="round">${polys.join('')}</g>` +
        `<text x="0" y="${num(-font / 2)}" font-size="${num(font)}">${escapeXml(`${surface.name}${surface.role === 'seeded' ? ' (seeded)' : ''}${offset}${ratio}`)}</text>` +
        `</g>`,
    );
    x += w + gap;
  });
  const totalWidth = x - gap;
  // Under the surfaces: the scale bar, then the headline's numbers, then the legend, each on its
  // own band, so nothing overlaps.
  const bar = niceScaleLength(widths[0] * 0.4);
  const barY = plotBottom + 1.2 * font;
  const headline = headlineLine(stack);
  const headlineY = barY + font * 2.6;
  const items: LegendItem[] = [
    ...SIDE_LABELS.map((label, k) => ({ swatch: `fill="${SIDE_COLORS[k]}"`, text: `${label} sides` })),
    { swatch: 'fill="url(#hatch)"', text: 'scutoid (hatched)' },
    // Faded cells lie on the surfaces' dark ground: the swatch is drawn the same way.
    { swatch: `fill="${SIDE_COLORS[3]}" fill-opacity="0.35"`, ground: '#282828', text: 'border cell (not counted)' },
  ];
  const legendWidth = Math.max(totalWidth, font * 30);
  const legend = legendSvg(items, 0, headlineY + font * 0.9, legendWidth, font);
  const totalHeight = headlineY + font * 0.9 + legend.height + font;
  const width = legendWidth + 2 * font;
  const provenance = provenanceLines(stack, 'tissue-sheet unrolled view (SVG, units µm)');
  const { result } = stack;
  return svgDocument({
    box: [-font, 0, width, totalHeight],
    widthMm: options.widthMm ?? DEFAULT_WIDTH_MM,
    unit: 'µm',
    title: `tissue-sheet ${result.software.version}: unrolled surfaces, seed ${result.seed}`,
    provenance,
    metadata: {
      software: result.software,
      seed: result.seed,
      engine: result.engine,
      method: stack.analysis?.method ?? null,
      headline: result.headline,
      config: result.config,
    },
    defs: `<pattern id="hatch" patternUnits="userSpaceOnUse" width="${num(font / 2)}" height="${num(font / 2)}" patternTransform="rotate(45)"><rect width="${num(font / 6)}" height="${num(font / 2)}" fill="#141414"/></pattern>`,
    body: [
      `<metadata id="tissue-sheet-config">${escapeXml(JSON.stringify(result.config))}</metadata>`,
      ...groups,
      `<g id="scale-bar" data-length-um="${bar}"><rect x="0" y="${num(barY)}" width="${num(bar)}" height="${num(font / 3)}" fill="#000"/>` +
        `<text x="0" y="${num(barY + font * 1.4)}" font-size="${num(font * 0.9)}">${bar} µm</text></g>`,
      `<text id="headline" x="0" y="${num(headlineY)}" font-size="${num(font * 0.9)}">${escapeXml(headline)}</text>`,
      `<g id="legend">${legend.svg}</g>`,
    ].join('\n'),
  });
}

/** The headline in one line for a figure: "% scutoids 37.1 % (mean of n = 5, 95 % CI 30.4–43.7 %), exact method, Voronoi 51". */
function headlineLine(stack: ViewStack): string {
  const h = stack.result.headline;
  if (!h || h.percentScutoids === null) return 'no % scutoids (no cell counted)';
  const over =
    h.realizations > 1 && h.ci95
      ? `mean of n = ${h.realizations}, 95 % CI ${h.ci95[0].toFixed(1)}–${h.ci95[1].toFixed(1)} %; cells shown: seed ${stack.result.seed}`
      : `one realization, seed ${stack.result.seed}`;
  return `${h.percentScutoids.toFixed(1)} % scutoids (${over}), ${h.method} method, Voronoi ${h.voronoiK}`;
}

/** Width of an SVG figure when none is chosen (a two-column journal figure). */
const DEFAULT_WIDTH_MM = 180;
