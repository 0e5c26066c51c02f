/**
 * Per-fragment cells on closed surfaces. A closed surface's cell at a point is the site nearest
 * to it in 3D (the restricted Voronoi diagram: the jump flood measures 3D distances too), so a
 * fragment can find its own cell exactly if it knows which sites might be nearest. Each vertex
 * of the atlas mesh (cubeAtlasMesh.ts) gets up to four candidate cells: the nearest sites among
 * the labels of the texels around it. WebGL passes a `flat` attribute from a triangle's last
 * vertex (the provoking vertex), and every vertex of a triangle lies within two steps of it, so
 * the candidates hold every label of the triangle: the fragment shader (closedMaterial.ts) and
 * picking (`nearestCandidate`) then pick the nearest candidate site to the exact point. Borders
 * are the true bisectors, sharp at any zoom, instead of colours interpolated between texels.
 * Pure data: no three.js, no DOM.
 */

/** Candidate cells per vertex. */
export const CANDIDATES = 4;

/**
 * Texel steps (across cube edges) searched around a vertex for candidates: 1 covers every vertex
 * of the vertex's triangles (so every fragment gets its own cell); 3 also finds the cell across
 * a nearby border when the triangle lies wholly inside one cell, so the border line is drawn on
 * both sides of it even on coarse atlases.
 */
const REACH = 3;
/** Texels within REACH 4-neighbour steps of a texel: 2 REACH (REACH + 1) + 1 on a face. */
const WINDOW = 2 * REACH * (REACH + 1) + 1;

/**
 * Up to CANDIDATES cell ids per vertex (-1: none) from the labels of the texels within REACH
 * steps of the vertex's texel (4-neighbour steps, across cube edges): those within two steps
 * first, nearest site first (so the vertex's own cell leads), then the farther ones.
 * `neighbours`: 4 texel neighbours per texel (atlasTopology); `sites`: xyz per cell.
 */
export function vertexCandidates(positions: ArrayLike<number>, labels: ArrayLike<number>, neighbours: Int32Array, sites: ArrayLike<number>): Float32Array {
  const count = labels.length;
  const out = new Float32Array(CANDIDATES * count).fill(-1);
  // Scratch, reused for every vertex: the window (breadth first), a stamp per texel (the last
  // vertex whose window holds it), and the window's distinct labels.
  const window = new Int32Array(WINDOW);
  const stamp = new Int32Array(count).fill(-1);
  const found = new Int32Array(WINDOW);
  const distance = new Float64Array(WINDOW);
  for (let v = 0; v < count; v++) {
    let size = 1;
    window[0] = v;
    stamp[v] = v;
    // Texels before `near` lie within two steps: they hold every label of v's triangles.
    let near = 1;
    for (let ring = 0, start = 0; ring < REACH; ring++) {
      const end = size;
      for (let w = start; w < end; w++) {
        for (let a = 0; a < 4; a++) {
          const texel = neighbours[4 * window[w] + a];
          if (stamp[texel] === v || size === WINDOW) continue;
          stamp[texel] = v;
          window[size++] = texel;
        }
      }
      start = end;
      if (ring === 1) near = size;
    }
    let distinct = 0;
    let nearDistinct = 0;
    for (let w = 0; w < size; w++) {
      if (w === near) nearDistinct = distinct;
      const id = labels[window[w]];
      // No cell, or a label without a site (never drawn as someone else's cell).
      if (id < 0 || 3 * id + 2 >= sites.length) continue;
      let seen = false;
      for (let k = 0; k < distinct && !seen; k++) seen = found[k] === id;
      if (!seen) found[distinct++] = id;
    }
    if (near >= size) nearDistinct = distinct;
    const x = positions[3 * v],
      y = positions[3 * v + 1],
      z = positions[3 * v + 2];
    for (let k = 0; k < distinct; k++) {
      const s = 3 * found[k];
      distance[k] = (x - sites[s]) ** 2 + (y - sites[s + 1]) ** 2 + (z - sites[s + 2]) ** 2;
    }
    // The labels within two steps first (the triangle's own cells), then the farther ones (a
    // border's other side), each group nearest first; the first CANDIDATES are kept.
    sortByDistance(found, distance, 0, nearDistinct);
    sortByDistance(found, distance, nearDistinct, distinct);
    for (let k = 0; k < Math.min(distinct, CANDIDATES); k++) out[CANDIDATES * v + k] = found[k];
  }
  return out;
}

/** Insertion sort of ids[from..to) by distance (a handful of entries). */
function sortByDistance(ids: Int32Array, distance: Float64Array, from: number, to: number): void {
  for (let k = from + 1; k < to; k++) {
    const id = ids[k],
      d = distance[k];
    let j = k - 1;
    for (; j >= from && distance[j] > d; j--) {
      ids[j + 1] = ids[j];
      distance[j + 1] = distance[j];
    }
    ids[j + 1] = id;
    distance[j + 1] = d;
  }
}

/**
 * The cell of point (x, y, z) on a triangle whose provoking vertex is `vertex`: the candidate
 * whose site is nearest (what the fragment shader draws there); -1 when the vertex has none.
 */
export function nearestCandidate(candidates: Float32Array, vertex: number, sites: ArrayLike<number>, x: number, y: number, z: number): number {
  let best = -1;
  let bestDistance = Infinity;
  for (let k = 0; k < CANDIDATES; k++) {
    const id = candidates[CANDIDATES * vertex + k];
    if (id < 0) continue;
    const s = 3 * id;
    const d = (x - sites[s]) ** 2 + (y - sites[s + 1]) ** 2 + (z - sites[s + 2]) ** 2;
    if (d < bestDistance) {
      bestDistance = d;
      best = id;
    }
  }
  return best;
}

/** xyz per cell of a surface's sites (µm), as the shader's site texture and picking read them. */
export function sitePositions(cells: readonly { position: readonly number[] }[]): Float32Array {
  const out = new Float32Array(3 * cells.length);
  cells.forEach((cell, i) => out.set(cell.position.slice(0, 3), 3 * i));
  return out;
}
