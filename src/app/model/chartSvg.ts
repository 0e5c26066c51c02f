/**
 * A chart as a journal takes it: an SVG at a chosen printed width (mm), axes with their labels
 * and units, ticks, each series' points (with their 95 % CI as a band or error bars, or ± SD for
 * reference points that give one), the mean's number beside each point, a legend under the plot
 * whose items never overlap (svgFigure.ts), notes (n, what the band is, fits), and the provenance
 * in <desc> and <metadata>. The sweep chart, the Flintstones fit and the measured-vs-model
 * comparison are drawn by it; figure.ts rasterizes it to a PNG at a chosen DPI.
 */
import { escapeXml, legendSvg, num, svgDocument, textWidth, type LegendItem } from './svgFigure';

interface ChartPoint {
  x: number;
  y: number;
  /** Interval drawn as an error bar (or a band for a line with `band`). */
  low?: number | null;
  high?: number | null;
}

export interface ChartSeries {
  label: string;
  color: string;
  points: readonly ChartPoint[];
  /** line: joined points; points: markers only; curve: a line without markers; bars: columns. */
  style: 'line' | 'points' | 'curve' | 'bars';
  dashed?: boolean;
  /** Draw low..high as a shaded band (lines) instead of error bars. */
  band?: boolean;
  /** Write each point's y beside it, with this many decimals. */
  labels?: number;
}

export interface ChartSpec {
  title: string;
  xLabel: string;
  yLabel: string;
  series: readonly ChartSeries[];
  /** Lines under the legend: n, what the band or bars mean, fitted parameters. */
  notes: readonly string[];
  yRange?: readonly [number, number];
  /** Categorical x (bars): tick labels at integer x. */
  xTicks?: readonly { x: number; label: string }[];
  provenance: readonly string[];
  metadata: unknown;
  widthMm: number;
}

/** 1, 2 or 5 x 10^n steps, about 5 of them over [lo, hi]. */
function niceTicks(lo: number, hi: number): number[] {
  if (!(hi > lo)) return [lo];
  const raw = (hi - lo) / 5;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) ?? 10 * power;
  const ticks: number[] = [];
  for (let t = Math.ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) ticks.push(Number(t.toPrecision(12)));
  return ticks;
}

const W = 520;
const FONT = 11;

export function chartSvg(spec: ChartSpec): string {
  const all = spec.series.flatMap((s) => s.points);
  const xs = all.map((p) => p.x);
  let xLo = Math.min(...xs);
  let xHi = Math.max(...xs);
  if (spec.xTicks || spec.series.some((s) => s.style === 'bars')) {
    xLo -= 0.6;
    xHi += 0.6;
  } else if (!(xHi > xLo)) {
    xLo -= 1;
    xHi += 1;
  } else {
    const pad = (xHi - xLo) * 0.04;
    xLo -= pad;
    xHi += pad;
  }
  const ys = all.flatMap((p) => [p.y, p.low ?? p.y, p.high ?? p.y]).filter(Number.isFinite);
  const [yLo, yHi] = spec.yRange ?? [Math.min(0, ...ys), Math.max(...ys) * 1.1 || 1];
  const left = FONT * 4.2;
  const right = FONT * 1.2;
  const top = FONT * 2.6;
  const plotW = W - left - right;
  const plotH = plotW * 0.55;
  const X = (x: number) => left + ((x - xLo) / (xHi - xLo)) * plotW;
  const Y = (y: number) => top + plotH - ((Math.max(yLo, Math.min(yHi, y)) - yLo) / (yHi - yLo)) * plotH;
  const out: string[] = [];
  out.push(`<text x="${num(left)}" y="${num(FONT * 1.3)}" font-size="${num(FONT * 1.15)}" font-weight="bold">${escapeXml(spec.title)}</text>`);
  // Axes, ticks and grid.
  out.push(`<g id="axes" stroke="#333" stroke-width="0.8" fill="none"><path d="M${num(left)} ${num(top)}V${num(top + plotH)}H${num(left + plotW)}"/></g>`);
  const yTicks = niceTicks(yLo, yHi);
  const grid: string[] = [];
  for (const t of yTicks) {
    grid.push(`<line x1="${num(left)}" x2="${num(left + plotW)}" y1="${num(Y(t))}" y2="${num(Y(t))}" stroke="#ddd" stroke-width="0.5"/>`);
    grid.push(`<text x="${num(left - 4)}" y="${num(Y(t) + FONT * 0.35)}" font-size="${num(FONT * 0.85)}" text-anchor="end">${t}</text>`);
  }
  const xTicks = spec.xTicks ?? niceTicks(Math.min(...xs), Math.max(...xs)).map((x) => ({ x, label: String(x) }));
  for (const t of xTicks) {
    grid.push(`<line x1="${num(X(t.x))}" x2="${num(X(t.x))}" y1="${num(top + plotH)}" y2="${num(top + plotH + 4)}" stroke="#333" stroke-width="0.8"/>`);
    grid.push(
      `<text x="${num(X(t.x))}" y="${num(top + plotH + FONT * 1.3)}" font-size="${num(FONT * 0.85)}" text-anchor="middle">${escapeXml(t.label)}</text>`,
    );
  }
  out.push(`<g id="grid">${grid.join('')}</g>`);
  out.push(
    `<text id="x-label" x="${num(left + plotW / 2)}" y="${num(top + plotH + FONT * 2.7)}" font-size="${num(FONT)}" text-anchor="middle">${escapeXml(spec.xLabel)}</text>`,
  );
  out.push(
    `<text id="y-label" transform="translate(${num(FONT * 1.1)} ${num(top + plotH / 2)}) rotate(-90)" font-size="${num(FONT)}" text-anchor="middle">${escapeXml(spec.yLabel)}</text>`,
  );
  // Series.
  const bars = spec.series.filter((s) => s.style === 'bars');
  const barWidth = bars.length ? Math.min(24, (plotW / Math.max(1, xTicks.length)) * 0.8) / bars.length : 0;
  spec.series.forEach((s, k) => {
    const g: string[] = [];
    const dash = s.dashed ? ' stroke-dasharray="5 3"' : '';
    const pts = s.points.filter((p) => Number.isFinite(p.y));
    if (s.band && pts.some((p) => p.low != null && p.high != null)) {
      const withCi = pts.filter((p) => p.low != null && p.high != null);
      const d = `M${withCi.map((p) => `${num(X(p.x))} ${num(Y(p.high!))}`).join('L')}L${[...withCi]
        .reverse()
        .map((p) => `${num(X(p.x))} ${num(Y(p.low!))}`)
        .join('L')}Z`;
      g.push(`<path class="band" d="${d}" fill="${s.color}" fill-opacity="0.18" stroke="none"/>`);
    }
    if (s.style === 'bars') {
      const b = bars.indexOf(s);
      for (const p of pts) {
        const x = X(p.x) - (bars.length * barWidth) / 2 + b * barWidth;
        g.push(`<rect x="${num(x)}" y="${num(Y(p.y))}" width="${num(barWidth * 0.9)}" height="${num(Math.max(0, Y(yLo) - Y(p.y)))}" fill="${s.color}"/>`);
      }
    }
    if (s.style === 'line' || s.style === 'curve') {
      g.push(
        `<polyline points="${pts.map((p) => `${num(X(p.x))},${num(Y(p.y))}`).join(' ')}" fill="none" stroke="${s.color}" stroke-width="${s.style === 'curve' ? 1.6 : 1.4}"${dash}/>`,
      );
    }
    if (s.style === 'line' || s.style === 'points') {
      for (const p of pts) {
        if (!s.band && p.low != null && p.high != null) {
          g.push(
            `<path class="error-bar" d="M${num(X(p.x))} ${num(Y(p.low))}V${num(Y(p.high))}M${num(X(p.x) - 3)} ${num(Y(p.low))}h6M${num(X(p.x) - 3)} ${num(Y(p.high))}h6" stroke="${s.color}" stroke-width="0.9" fill="none"/>`,
          );
        }
        g.push(`<circle cx="${num(X(p.x))}" cy="${num(Y(p.y))}" r="2.6" fill="${s.color}"/>`);
      }
    }
    if (s.labels !== undefined) {
      for (const p of pts) {
        g.push(
          `<text class="value" x="${num(X(p.x) + 4)}" y="${num(Y(p.y) - 4)}" font-size="${num(FONT * 0.7)}" fill="${s.color}">${p.y.toFixed(s.labels)}</text>`,
        );
      }
    }
    out.push(`<g class="series" data-series="${k}" data-label="${escapeXml(s.label)}">${g.join('')}</g>`);
  });
  // Legend and notes under the plot.
  const items: LegendItem[] = spec.series.map((s) => ({
    swatch: s.style === 'bars' ? `fill="${s.color}"` : `fill="${s.color}"${s.dashed ? ' fill-opacity="0.45"' : ''}`,
    text: `${s.label}${s.dashed ? ' (dashed)' : ''}`,
  }));
  const legendTop = top + plotH + FONT * 3.6;
  const legend = legendSvg(items, left, legendTop, plotW, FONT);
  out.push(`<g id="legend">${legend.svg}</g>`);
  let y = legendTop + legend.height + FONT * 0.4;
  const notes: string[] = [];
  for (const note of spec.notes) {
    // Wrap notes to the plot's width.
    let line = '';
    for (const word of note.split(' ')) {
      const next = line ? `${line} ${word}` : word;
      if (textWidth(next, FONT * 0.8) > W - left && line) {
        notes.push(line);
        line = word;
      } else line = next;
    }
    if (line) notes.push(line);
  }
  const noteSvg = notes.map((line) => {
    y += FONT * 1.15;
    return `<text class="note" x="${num(left)}" y="${num(y)}" font-size="${num(FONT * 0.8)}">${escapeXml(line)}</text>`;
  });
  out.push(`<g id="notes">${noteSvg.join('')}</g>`);
  const height = y + FONT;
  return svgDocument({
    box: [0, 0, W, height],
    widthMm: spec.widthMm,
    unit: 'chart units',
    title: spec.title,
    provenance: spec.provenance,
    metadata: spec.metadata,
    body: `<rect width="${W}" height="${num(height)}" fill="#fff"/>\n${out.join('\n')}`,
  });
}
