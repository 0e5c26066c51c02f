/**
 * The unrolled view as SVG: every surface of a plane or tube side by side at its true
 * proportions (user units = µm), each cell its exact polygon (cellPolygons.ts) filled with its
 * side colour, border cells faded, scutoids hatched, with captions, a legend, a scale bar and the
 * provenance in <metadata>/<desc>. A tube's surface is periodic around x: polygons unwrapped
 * past the seam are drawn again one circumference over and clipped to the strip. Every polygon
 * carries data-cell, data-surface, data-sides, data-scutoid and data-valid, so a reader (and the
 * tests) can take the figure back to the numbers. Closed surfaces cannot be unrolled: refused.
 */
import { SIDE_COLORS, SIDE_LABELS, sideColorIndex } from '../../view/sideColors';
import type { ViewStack } from '../../view/stack';
import { surfacePolygons } from '../../view/cellPolygons';
import { provenanceLines } from './cellRows';
import { niceScaleLength } from './scaleBar';

const GAP_FRACTION = 0.06;

export function unrolledSvg(stack: ViewStack): string {
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
  // Scale bar under the first surface; legend under the rest.
  const bar = niceScaleLength(widths[0] * 0.4);
  const barY = plotBottom + 1.5 * font;
  const legendItems = SIDE_LABELS.map((label, k) => [SIDE_COLORS[k], `${label} sides`] as const);
  const legend: string[] = [];
  let lx = Math.min(widths[0] * 0.5 + gap, totalWidth * 0.3);
  const itemWidth = font * 5.5;
  let ly = barY - font * 0.8;
  const legendRight = Math.max(totalWidth, lx + 4 * itemWidth);
  const place = (swatch: string, text: string) => {
    if (lx + itemWidth > legendRight) {
      lx = Math.min(widths[0] * 0.5 + gap, totalWidth * 0.3);
      ly += font * 1.4;
    }
    legend.push(`<rect x="${num(lx)}" y="${num(ly)}" width="${num(font)}" height="${num(font)}" ${swatch} stroke="#1a1a1a" stroke-width="${num(font / 12)}"/>`);
    legend.push(`<text x="${num(lx + font * 1.3)}" y="${num(ly + font * 0.85)}" font-size="${num(font * 0.8)}">${escapeXml(text)}</text>`);
    lx += itemWidth;
  };
  for (const [color, text] of legendItems) place(`fill="${color}"`, text);
  place('fill="url(#hatch)"', 'scutoid (hatched)');
  place(`fill="${SIDE_COLORS[3]}" fill-opacity="0.35"`, 'border cell (not counted)');
  const totalHeight = ly + font * 2.5;
  const provenance = provenanceLines(stack, 'tissue-sheet unrolled view (SVG, units µm)');
  return [
    `<?xml version="1.0" encoding="UTF-8"?>`,
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${num(-font)} 0 ${num(legendRight + 2 * font)} ${num(totalHeight)}" width="${num(legendRight + 2 * font)}mm" height="${num(totalHeight)}mm" font-family="sans-serif" data-units="um">`,
    `<title>tissue-sheet ${escapeXml(stack.result.software.version)}: unrolled surfaces, seed ${stack.result.seed}</title>`,
    `<desc>${escapeXml(provenance.join('\n'))}</desc>`,
    `<metadata id="tissue-sheet-config">${escapeXml(JSON.stringify(stack.result.config))}</metadata>`,
    `<defs><pattern id="hatch" patternUnits="userSpaceOnUse" width="${num(font / 2)}" height="${num(font / 2)}" patternTransform="rotate(45)"><rect width="${num(font / 6)}" height="${num(font / 2)}" fill="#141414"/></pattern></defs>`,
    ...groups,
    `<g id="scale-bar" data-length-um="${bar}"><rect x="0" y="${num(barY)}" width="${num(bar)}" height="${num(font / 3)}" fill="#000"/>` +
      `<text x="0" y="${num(barY + font * 1.4)}" font-size="${num(font * 0.9)}">${bar} µm</text></g>`,
    `<g id="legend">${legend.join('')}</g>`,
    `</svg>`,
  ].join('\n');
}

function num(value: number): string {
  return String(Math.round(value * 1000) / 1000);
}

function escapeXml(text: string): string {
  return text.replace(/[&<>"']/g, (ch) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&apos;' })[ch]!);
}
