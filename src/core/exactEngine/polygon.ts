/**
 * Convex-polygon helpers for the exact engine, on flat buffers (interleaved x, y) so the Lloyd
 * loop allocates nothing: half-plane clipping that carries a label per edge, and the closed-form
 * moments of a uniform polygon.
 *
 * A labelled polygon is (xy, labels, count): vertex k at xy[2k], xy[2k+1]; labels[k] names the
 * edge from vertex k to vertex k+1 (mod count). Either orientation is accepted everywhere.
 */

/** Growable scratch polygon: vertices and one label per edge. */
export class PolygonBuffer {
  xy: Float64Array;
  labels: Int32Array;
  count = 0;

  constructor(capacity = 32) {
    this.xy = new Float64Array(2 * capacity);
    this.labels = new Int32Array(capacity);
  }

  clear(): void {
    this.count = 0;
  }

  push(x: number, y: number, label: number): void {
    if (this.count === this.labels.length) this.grow();
    this.xy[2 * this.count] = x;
    this.xy[2 * this.count + 1] = y;
    this.labels[this.count] = label;
    this.count++;
  }

  private grow(): void {
    const xy = new Float64Array(this.xy.length * 2);
    xy.set(this.xy);
    const labels = new Int32Array(this.labels.length * 2);
    labels.set(this.labels);
    this.xy = xy;
    this.labels = labels;
  }
}

/**
 * Keeps the part of `source` where sign * (coordinate `axis` - value) >= 0 (axis 0 = x, 1 = y) and
 * writes it to `target`. Kept parts of edges keep their label; the new edge along the cut line
 * gets `cutLabel` (Sutherland–Hodgman; exact for convex polygons).
 */
export function clipHalfPlane(source: PolygonBuffer, target: PolygonBuffer, axis: 0 | 1, value: number, sign: 1 | -1, cutLabel: number): void {
  target.clear();
  const n = source.count;
  const xy = source.xy;
  for (let k = 0; k < n; k++) {
    const l = k + 1 === n ? 0 : k + 1;
    const ax = xy[2 * k];
    const ay = xy[2 * k + 1];
    const bx = xy[2 * l];
    const by = xy[2 * l + 1];
    const da = sign * ((axis === 0 ? ax : ay) - value);
    const db = sign * ((axis === 0 ? bx : by) - value);
    const label = source.labels[k];
    if (da >= 0) {
      if (db >= 0) target.push(ax, ay, label);
      else {
        target.push(ax, ay, label);
        const t = da / (da - db);
        target.push(ax + (bx - ax) * t, ay + (by - ay) * t, cutLabel);
      }
    } else if (db >= 0) {
      const t = da / (da - db);
      target.push(ax + (bx - ax) * t, ay + (by - ay) * t, label);
    }
  }
}

/** Moments of a uniform polygon about the origin: [area, ∫x, ∫y, ∫(x² + y²)], orientation-free. */
export function polygonMoments(xy: Float64Array, count: number, out: Float64Array): Float64Array {
  let a2 = 0;
  let mx = 0;
  let my = 0;
  let i2 = 0;
  for (let k = 0; k < count; k++) {
    const l = k + 1 === count ? 0 : k + 1;
    const x0 = xy[2 * k];
    const y0 = xy[2 * k + 1];
    const x1 = xy[2 * l];
    const y1 = xy[2 * l + 1];
    const cross = x0 * y1 - x1 * y0;
    a2 += cross;
    mx += (x0 + x1) * cross;
    my += (y0 + y1) * cross;
    i2 += (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1) * cross;
  }
  const sign = a2 < 0 ? -1 : 1;
  out[0] = (sign * a2) / 2;
  out[1] = (sign * mx) / 6;
  out[2] = (sign * my) / 6;
  out[3] = (sign * i2) / 12;
  return out;
}

/** Axis-aligned extent of a polygon along `axis`: [min, max] written into out. */
export function polygonExtent(xy: Float64Array, count: number, axis: 0 | 1, out: Float64Array): Float64Array {
  let lo = Infinity;
  let hi = -Infinity;
  for (let k = 0; k < count; k++) {
    const v = xy[2 * k + axis];
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
  out[0] = lo;
  out[1] = hi;
  return out;
}
