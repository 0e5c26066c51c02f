/**
 * What every figure's SVG shares (issue 26, figures a journal takes): physical size (the SVG's
 * width and height in mm, the chosen width; the viewBox in the figure's own units, so 1 mm on
 * paper is a known number of them), a legend laid out from estimated text widths so that no
 * swatch or text overlaps another (each item a `<g class="legend-item">` with its box in
 * data-box), the provenance (version, seed, engine, method, headline, configuration) in
 * `<metadata>` as JSON and in `<desc>` as lines.
 */

/** Width of `text` at `size` in a sans-serif font, estimated generously (0.62 em per character). */
export function textWidth(text: string, size: number): number {
  return [...text].length * size * 0.62;
}

export interface LegendItem {
  /** SVG attributes of the swatch rect (fill, opacity, pattern). */
  swatch: string;
  text: string;
  /** Drawn under the swatch first (e.g. the dark ground faded cells lie on). */
  ground?: string;
}

/**
 * A legend from `x`, `y` (top-left) within `maxWidth`: items left to right, wrapping to a new
 * row where the next would not fit; each item's box (swatch and text) is disjoint from every
 * other's. Returns the SVG and the height used.
 */
export function legendSvg(items: readonly LegendItem[], x: number, y: number, maxWidth: number, font: number): { svg: string; height: number } {
  const size = font * 0.8;
  const gap = font * 0.9;
  const out: string[] = [];
  let lx = x;
  let ly = y;
  const rowHeight = font * 1.5;
  for (const item of items) {
    const width = font * 1.3 + textWidth(item.text, size);
    if (lx > x && lx + width > x + maxWidth) {
      lx = x;
      ly += rowHeight;
    }
    out.push(
      `<g class="legend-item" data-box="${num(lx)} ${num(ly)} ${num(width)} ${num(font)}">` +
        (item.ground ? `<rect x="${num(lx)}" y="${num(ly)}" width="${num(font)}" height="${num(font)}" fill="${item.ground}"/>` : '') +
        `<rect class="legend-swatch" x="${num(lx)}" y="${num(ly)}" width="${num(font)}" height="${num(font)}" ${item.swatch} stroke="#1a1a1a" stroke-width="${num(font / 12)}"/>` +
        `<text class="legend-text" x="${num(lx + font * 1.3)}" y="${num(ly + font * 0.82)}" font-size="${num(size)}">${escapeXml(item.text)}</text></g>`,
    );
    lx += width + gap;
  }
  return { svg: out.join(''), height: ly - y + rowHeight };
}

export interface SvgDocument {
  /** The viewBox: x, y, width, height in the figure's units. */
  box: readonly [number, number, number, number];
  /** Printed width (mm); the height follows the viewBox's aspect. */
  widthMm: number;
  /** What one user unit is ("µm" for cells, "pt" for charts). */
  unit: string;
  title: string;
  provenance: readonly string[];
  metadata: unknown;
  defs?: string;
  body: string;
}

/** An SVG document in physical units: width and height in mm, provenance in <desc> and <metadata>. */
export function svgDocument(doc: SvgDocument): string {
  const [x, y, w, h] = doc.box;
  const heightMm = (doc.widthMm * h) / w;
  const perMm = w / doc.widthMm;
  return [
    `<?xml version="1.0" encoding="UTF-8"?>`,
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${num(x)} ${num(y)} ${num(w)} ${num(h)}" width="${num(doc.widthMm)}mm" height="${num(heightMm)}mm" font-family="sans-serif" data-units="${escapeXml(doc.unit)}" data-units-per-mm="${num(perMm)}">`,
    `<title>${escapeXml(doc.title)}</title>`,
    `<desc>${escapeXml([...doc.provenance, `printed ${num(doc.widthMm)} mm wide: 1 mm on paper is ${num(perMm)} ${doc.unit}`].join('\n'))}</desc>`,
    `<metadata id="tissue-sheet-provenance">${escapeXml(JSON.stringify(doc.metadata))}</metadata>`,
    doc.defs ? `<defs>${doc.defs}</defs>` : '',
    doc.body,
    `</svg>`,
  ]
    .filter((line) => line !== '')
    .join('\n');
}

export function num(value: number): string {
  return String(Math.round(value * 1000) / 1000);
}

export function escapeXml(text: string): string {
  return text.replace(/[&<>"']/g, (ch) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&apos;' })[ch]!);
}
