/**
 * What the solid of a cell (cellSolid.ts) is built from: a cross-section per surface, as a convex
 * polygon in a 2D frame tangent at the cell's site, with the map from that frame to 3D; and the
 * small vector and polygon helpers both kinds of cross-section use. Pure geometry.
 */

export type Vec3 = [number, number, number];

/** A cross-section: its polygon in the tangent frame and how a frame point goes to 3D. */
export interface Section {
  polygon: Float64Array;
  centre: Vec3;
  toSpace(x: number, y: number): Vec3;
}

/** A square of half-width `half` around the origin, counter-clockwise. */
export function square(half: number): Float64Array {
  return Float64Array.from([-half, -half, half, -half, half, half, -half, half]);
}

/** Sutherland–Hodgman: the part of a convex polygon with a x + b y <= c. */
export function clipHalfPlane(polygon: Float64Array, a: number, b: number, c: number): Float64Array {
  const out: number[] = [];
  const n = polygon.length / 2;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    const px = polygon[2 * i];
    const py = polygon[2 * i + 1];
    const qx = polygon[2 * j];
    const qy = polygon[2 * j + 1];
    const fp = a * px + b * py - c;
    const fq = a * qx + b * qy - c;
    if (fp <= 0) out.push(px, py);
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
      const t = fp / (fp - fq);
      out.push(px + t * (qx - px), py + t * (qy - py));
    }
  }
  return Float64Array.from(out);
}

export const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const dist2 = (a: Vec3, b: ArrayLike<number>): number => (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 + (a[2] - b[2]) ** 2;
export const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const normalize = (a: Vec3): Vec3 => scale(a, 1 / (Math.hypot(a[0], a[1], a[2]) || 1));
