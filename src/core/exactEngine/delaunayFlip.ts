/**
 * Restores the Delaunay property of a triangulation whose points have moved (Lawson's edge
 * flips), instead of triangulating them anew: the layers of a tube are the same sites with the
 * circumference scaled, so the previous layer's triangulation is nearly Delaunay for the next one
 * and a few flips per layer replace a whole sweep-hull triangulation.
 *
 * Lawson's algorithm gives the Delaunay triangulation of the points when it starts from any
 * valid triangulation of their convex hull. So the moved triangulation is checked first: every
 * triangle still strictly positively oriented (robust orient2d, Delaunator's orientation) and
 * the hull still convex (a straight angle allowed); otherwise, or when the flips do not settle,
 * `restoreDelaunay` returns false and the caller triangulates afresh. Edges are tested with
 * Delaunator's own in-circle test (the one every fresh triangulation ends with), and the result
 * is checked once more for inverted triangles. Where the Delaunay triangulation is unique (no
 * four cocircular points) it is the one a fresh triangulation gives, triangle for triangle up to
 * order; with cocircular points either diagonal may remain, whose dual Voronoi edge has length 0
 * (exactSurface drops it: the same neighbour sets).
 */
import { orient2d } from 'robust-predicates';
import { inCircle, type Triangulation } from './delaunay';

/** Flips allowed per half-edge before giving up (rounding could make the flips cycle). */
const MAX_FLIPS_PER_EDGE = 20;

let stack = new Int32Array(1024);
/** Triangles made by the flips (checked for orientation at the end). */
let made = new Int32Array(1024);
let hullOut = new Int32Array(1024);
let hullEdges = new Int32Array(1024);

/**
 * Makes `t` (a triangulation of the first t.count points of `coords`, which have moved since it
 * was built) Delaunay again by edge flips and recomputes its `inedges`. False, with `t` left in
 * an unspecified state, when the moved triangulation is not a valid one of the convex hull.
 */
export function restoreDelaunay(t: Triangulation, coords: Float64Array): boolean {
  const { triangles, halfedges, length } = t;
  if (length === 0) return false;
  if (stack.length < length) stack = new Int32Array(length);
  let top = validMoved(t, coords);
  if (top < 0) return false;
  let flips = 0;
  const maxFlips = MAX_FLIPS_PER_EDGE * length;
  while (top > 0) {
    const a = stack[--top];
    const b = halfedges[a];
    if (b === -1) continue;
    const a0 = a - (a % 3);
    const b0 = b - (b % 3);
    const al = a0 + ((a + 1) % 3);
    const ar = a0 + ((a + 2) % 3);
    const bl = b0 + ((b + 2) % 3);
    const br = b0 + ((b + 1) % 3);
    const p0 = 2 * triangles[ar];
    const pr = 2 * triangles[a];
    const pl = 2 * triangles[al];
    const p1 = 2 * triangles[bl];
    if (!inCircle(coords[p0], coords[p0 + 1], coords[pr], coords[pr + 1], coords[pl], coords[pl + 1], coords[p1], coords[p1 + 1])) continue;
    if (++flips > maxFlips) return false;
    if (2 * flips > made.length) {
      const grown = new Int32Array(2 * made.length);
      grown.set(made);
      made = grown;
    }
    made[2 * flips - 2] = a0;
    made[2 * flips - 1] = b0;
    // Delaunator's flip (legalize): the quad's diagonal pr-pl becomes p0-p1.
    triangles[a] = p1 / 2;
    triangles[b] = p0 / 2;
    const hbl = halfedges[bl];
    link(halfedges, a, hbl);
    link(halfedges, b, halfedges[ar]);
    link(halfedges, ar, bl);
    // The quad's four sides may have become illegal.
    if (top + 4 > stack.length) {
      const grown = new Int32Array(2 * stack.length);
      grown.set(stack);
      stack = grown;
    }
    stack[top++] = a;
    stack[top++] = al;
    stack[top++] = b;
    stack[top++] = br;
  }
  for (let k = 0; k < 2 * flips; k++) if (!positive(triangles, made[k], coords)) return false;
  const { inedges } = t;
  inedges.fill(-1, 0, t.count);
  for (let e = 0; e < length; e += 3) {
    setInedge(inedges, halfedges, e, triangles[e + 1]);
    setInedge(inedges, halfedges, e + 1, triangles[e + 2]);
    setInedge(inedges, halfedges, e + 2, triangles[e]);
  }
  return true;
}

/** Half-edge e ends at p: p's inedge, a hull edge where p has one (as Triangulation.triangulate). */
function setInedge(inedges: Int32Array, halfedges: Int32Array, e: number, p: number): void {
  if (halfedges[e] === -1 || inedges[p] === -1) inedges[p] = e;
}

/**
 * In one pass: every triangle strictly positive, the interior edges onto the flip stack (once
 * each), the hull edges noted; then the hull convex (each turn left or straight). Returns the
 * stack's size, -1 where the moved triangulation is not valid.
 */
function validMoved(t: Triangulation, coords: Float64Array): number {
  const { triangles, halfedges, length, count } = t;
  if (hullOut.length < count) hullOut = new Int32Array(Math.ceil(count * 1.25));
  if (hullEdges.length < length) hullEdges = new Int32Array(length);
  let top = 0;
  let hull = 0;
  for (let e0 = 0; e0 < length; e0 += 3) {
    if (!positive(triangles, e0, coords)) return -1;
    for (let e = e0; e < e0 + 3; e++) {
      const twin = halfedges[e];
      if (twin > e) stack[top++] = e;
      else if (twin === -1) {
        // The hull edge leaving each hull point, to its end.
        hullOut[triangles[e]] = triangles[e === e0 + 2 ? e0 : e + 1];
        hullEdges[hull++] = e;
      }
    }
  }
  for (let k = 0; k < hull; k++) {
    const e = hullEdges[k];
    const a = 2 * triangles[e];
    const bi = hullOut[triangles[e]];
    const b = 2 * bi;
    const c = 2 * hullOut[bi];
    if (orient2d(coords[a], coords[a + 1], coords[b], coords[b + 1], coords[c], coords[c + 1]) < 0) return -1;
  }
  return top;
}

/** Whether the triangle at half-edge e (a multiple of 3) is strictly positively oriented. */
function positive(triangles: Uint32Array, e: number, coords: Float64Array): boolean {
  const a = 2 * triangles[e];
  const b = 2 * triangles[e + 1];
  const c = 2 * triangles[e + 2];
  return orient2d(coords[a], coords[a + 1], coords[b], coords[b + 1], coords[c], coords[c + 1]) > 0;
}

function link(halfedges: Int32Array, a: number, b: number): void {
  halfedges[a] = b;
  if (b !== -1) halfedges[b] = a;
}
