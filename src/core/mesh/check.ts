/**
 * Topology checks for the surfaces tissue-sheet can tessellate.
 *
 * The spherical parameterization and the cube-map geometry image only exist for a closed,
 * connected, manifold, consistently oriented surface of genus 0, so everything else has to be
 * rejected up front with a message a biologist can act on ("what" and "where"), not with a
 * wrong tessellation.
 */
import { boundingBox, faceAreas, signedVolume, type TriangleMesh } from './types';

type MeshProblemKind =
  | 'empty'
  | 'unreferenced-vertices'
  | 'degenerate-face'
  | 'duplicate-face'
  | 'open'
  | 'non-manifold-edge'
  | 'non-manifold-vertex'
  | 'orientation'
  | 'inward'
  | 'flat'
  | 'components'
  | 'genus';

export interface MeshProblem {
  kind: MeshProblemKind;
  /** 'error': the mesh cannot be used. 'warning': it can (we fix or ignore it), but you should know. */
  severity: 'error' | 'warning';
  message: string;
  /** How many faces / edges / vertices / components are affected. */
  count: number;
}

export interface MeshTopology {
  vertices: number;
  edges: number;
  faces: number;
  /** V - E + F over referenced vertices. */
  eulerCharacteristic: number;
  components: number;
  boundaryEdges: number;
  nonManifoldEdges: number;
  /** (2 - χ) / 2 for a closed connected orientable manifold, else null. */
  genus: number | null;
}

const fmt = (x: number) => (Math.abs(x) >= 1e4 || (Math.abs(x) < 1e-3 && x !== 0) ? x.toExponential(3) : x.toFixed(4).replace(/\.?0+$/, ''));

function pos(mesh: TriangleMesh, v: number): string {
  const p = mesh.positions;
  return `(${fmt(p[3 * v])}, ${fmt(p[3 * v + 1])}, ${fmt(p[3 * v + 2])})`;
}

class UnionFind {
  parent: Int32Array;
  constructor(n: number) {
    this.parent = new Int32Array(n);
    for (let i = 0; i < n; i++) this.parent[i] = i;
  }
  find(i: number): number {
    while (this.parent[i] !== i) {
      this.parent[i] = this.parent[this.parent[i]];
      i = this.parent[i];
    }
    return i;
  }
  union(a: number, b: number): void {
    const ra = this.find(a),
      rb = this.find(b);
    if (ra !== rb) this.parent[ra] = rb;
  }
}

/** The mesh's vertices joined when they share a face: its connected components. */
function faceComponents(mesh: TriangleMesh): UnionFind {
  const t = mesh.indices;
  const uf = new UnionFind(mesh.positions.length / 3);
  for (let f = 0; f < t.length; f += 3) {
    uf.union(t[f], t[f + 1]);
    uf.union(t[f], t[f + 2]);
  }
  return uf;
}

interface EdgeInfo {
  a: number;
  b: number;
  /** Faces using this edge, and whether each traverses it as a -> b (true) or b -> a. */
  faces: number[];
  forward: boolean[];
}

/** Undirected edges of the mesh with their incident faces. Key: min * V + max. */
function buildEdges(mesh: TriangleMesh): Map<number, EdgeInfo> {
  const t = mesh.indices;
  const nv = mesh.positions.length / 3;
  const edges = new Map<number, EdgeInfo>();
  for (let f = 0; f < t.length / 3; f++) {
    for (let k = 0; k < 3; k++) {
      const u = t[3 * f + k],
        w = t[3 * f + ((k + 1) % 3)];
      if (u === w) continue;
      const a = Math.min(u, w),
        b = Math.max(u, w);
      const key = a * nv + b;
      let e = edges.get(key);
      if (!e) {
        e = { a, b, faces: [], forward: [] };
        edges.set(key, e);
      }
      e.faces.push(f);
      e.forward.push(u === a);
    }
  }
  return edges;
}

/** Counts of the Euler characteristic and related numbers (no judgement). */
export function meshTopology(mesh: TriangleMesh): MeshTopology {
  const t = mesh.indices;
  const nv = mesh.positions.length / 3;
  const nf = t.length / 3;
  const used = new Uint8Array(nv);
  for (const i of t) used[i] = 1;
  let V = 0;
  for (const u of used) V += u;
  const edges = buildEdges(mesh);
  let boundary = 0,
    nonManifold = 0;
  for (const e of edges.values()) {
    if (e.faces.length === 1) boundary++;
    else if (e.faces.length > 2) nonManifold++;
  }
  const uf = faceComponents(mesh);
  const roots = new Set<number>();
  for (let v = 0; v < nv; v++) if (used[v]) roots.add(uf.find(v));
  const chi = V - edges.size + nf;
  const genus = boundary === 0 && nonManifold === 0 && roots.size === 1 && chi % 2 === 0 ? (2 - chi) / 2 : null;
  return {
    vertices: V,
    edges: edges.size,
    faces: nf,
    eulerCharacteristic: chi,
    components: roots.size,
    boundaryEdges: boundary,
    nonManifoldEdges: nonManifold,
    genus,
  };
}

/**
 * Lists everything that keeps `mesh` from being a closed genus-0 sheet. An empty list (or only
 * warnings) means the mesh can be parameterized onto the sphere.
 */
export function checkMesh(mesh: TriangleMesh): MeshProblem[] {
  const problems: MeshProblem[] = [];
  const t = mesh.indices;
  const nv = mesh.positions.length / 3;
  const nf = t.length / 3;
  if (nf === 0 || nv === 0) {
    return [{ kind: 'empty', severity: 'error', message: 'the mesh has no triangles', count: 0 }];
  }
  const used = new Uint8Array(nv);
  for (const i of t) used[i] = 1;
  const unused = nv - used.reduce((s, u) => s + u, 0);
  if (unused > 0) {
    const first = used.indexOf(0);
    problems.push({
      kind: 'unreferenced-vertices',
      severity: 'warning',
      message: `${unused} vertices are used by no triangle (first: vertex ${first} at ${pos(mesh, first)}); they are ignored`,
      count: unused,
    });
  }

  // Degenerate faces: repeated vertex ids, or (numerically) zero area.
  const diag = boundingBox(mesh.positions).diagonal;
  const areas = faceAreas(mesh);
  const areaEps = 1e-12 * diag * diag;
  let repeated = 0,
    zero = 0,
    firstRepeated = -1,
    firstZero = -1;
  for (let f = 0; f < nf; f++) {
    const a = t[3 * f],
      b = t[3 * f + 1],
      c = t[3 * f + 2];
    if (a === b || b === c || a === c) {
      repeated++;
      if (firstRepeated < 0) firstRepeated = f;
    } else if (areas[f] <= areaEps) {
      zero++;
      if (firstZero < 0) firstZero = f;
    }
  }
  if (repeated > 0) {
    const f = firstRepeated;
    problems.push({
      kind: 'degenerate-face',
      severity: 'error',
      message: `${repeated} degenerate faces repeat a vertex (first: face ${f} = (${t[3 * f]}, ${t[3 * f + 1]}, ${t[3 * f + 2]}) at ${pos(mesh, t[3 * f])})`,
      count: repeated,
    });
  }
  if (zero > 0) {
    const f = firstZero;
    problems.push({
      kind: 'degenerate-face',
      severity: 'error',
      message: `${zero} degenerate faces have zero area (collinear vertices; first: face ${f} = (${t[3 * f]}, ${t[3 * f + 1]}, ${t[3 * f + 2]}) at ${pos(mesh, t[3 * f])})`,
      count: zero,
    });
  }

  // Duplicate faces: the same three vertices, whatever their order.
  const seen = new Map<string, number>();
  let dup = 0;
  let dupPair: [number, number] | null = null;
  for (let f = 0; f < nf; f++) {
    const key = [t[3 * f], t[3 * f + 1], t[3 * f + 2]].sort((x, y) => x - y).join(',');
    const g = seen.get(key);
    if (g !== undefined) {
      dup++;
      dupPair ??= [g, f];
    } else seen.set(key, f);
  }
  if (dupPair) {
    const [g, f] = dupPair;
    problems.push({
      kind: 'duplicate-face',
      severity: 'error',
      message: `${dup} duplicate faces (first: faces ${g} and ${f} both use vertices ${[t[3 * f], t[3 * f + 1], t[3 * f + 2]].sort((x, y) => x - y).join(', ')} at ${pos(mesh, t[3 * f])})`,
      count: dup,
    });
  }

  // Edges: boundary (1 face), non-manifold (> 2 faces), orientation (2 faces, same direction).
  const edges = buildEdges(mesh);
  let boundary: EdgeInfo[] = [];
  let nonManifold: EdgeInfo[] = [];
  let inconsistent = 0;
  let firstInconsistent: EdgeInfo | null = null;
  for (const e of edges.values()) {
    if (e.faces.length === 1) boundary.push(e);
    else if (e.faces.length > 2) nonManifold.push(e);
    else if (e.forward[0] === e.forward[1]) {
      inconsistent++;
      firstInconsistent ??= e;
    }
  }
  if (boundary.length > 0) {
    // Count boundary loops (holes) by joining boundary edges at their vertices.
    const uf = new UnionFind(nv);
    for (const e of boundary) uf.union(e.a, e.b);
    const loops = new Set(boundary.map((e) => uf.find(e.a))).size;
    const e = boundary[0];
    problems.push({
      kind: 'open',
      severity: 'error',
      message:
        `not closed: ${boundary.length} boundary edges (edges with only one face) forming ${loops} hole${loops > 1 ? 's' : ''}; ` +
        `the first joins vertices ${e.a} ${pos(mesh, e.a)} and ${e.b} ${pos(mesh, e.b)}. tissue-sheet needs a closed surface (close the holes or re-export as a watertight mesh)`,
      count: boundary.length,
    });
  }
  if (nonManifold.length > 0) {
    const e = nonManifold[0];
    problems.push({
      kind: 'non-manifold-edge',
      severity: 'error',
      message: `${nonManifold.length} non-manifold edges are shared by more than 2 faces (first: edge ${e.a}-${e.b} at ${pos(mesh, e.a)} is used by ${e.faces.length} faces: ${e.faces.join(', ')})`,
      count: nonManifold.length,
    });
  }
  if (inconsistent > 0 && firstInconsistent) {
    const e = firstInconsistent;
    problems.push({
      kind: 'orientation',
      severity: 'error',
      message: `inconsistent orientation: ${inconsistent} edges are traversed in the same direction by both of their faces (first: edge ${e.a}-${e.b} at ${pos(mesh, e.a)}, faces ${e.faces[0]} and ${e.faces[1]}); some triangles are flipped`,
      count: inconsistent,
    });
  }

  // Non-manifold vertices: the faces around a vertex must form a single fan (no "bow tie").
  const vf = vertexFaces(mesh);
  let badVertices = 0,
    firstBad = -1;
  for (let v = 0; v < nv; v++) {
    const start = vf.offsets[v],
      end = vf.offsets[v + 1];
    const k = end - start;
    if (k === 0) continue;
    const uf = new UnionFind(k);
    const byOther = new Map<number, number>();
    for (let s = 0; s < k; s++) {
      const f = vf.faces[start + s];
      for (let c = 0; c < 3; c++) {
        const w = t[3 * f + c];
        if (w === v) continue;
        const prev = byOther.get(w);
        if (prev !== undefined) uf.union(prev, s);
        else byOther.set(w, s);
      }
    }
    let groups = 0;
    for (let s = 0; s < k; s++) if (uf.find(s) === s) groups++;
    if (groups > 1) {
      badVertices++;
      if (firstBad < 0) firstBad = v;
    }
  }
  if (badVertices > 0) {
    problems.push({
      kind: 'non-manifold-vertex',
      severity: 'error',
      message: `${badVertices} non-manifold vertices join separate fans of faces (first: vertex ${firstBad} at ${pos(mesh, firstBad)}); the surface touches itself at a point`,
      count: badVertices,
    });
  }

  // Connected components (through shared vertices).
  const uf = faceComponents(mesh);
  const sizes = new Map<number, number>();
  for (let f = 0; f < nf; f++) {
    const r = uf.find(t[3 * f]);
    sizes.set(r, (sizes.get(r) ?? 0) + 1);
  }
  if (sizes.size > 1) {
    const list = [...sizes.values()].sort((a, b) => b - a);
    problems.push({
      kind: 'components',
      severity: 'error',
      message: `the mesh has ${sizes.size} separate connected components (faces per component: ${list.slice(0, 5).join(', ')}${list.length > 5 ? ', ...' : ''}); tissue-sheet needs one surface: keep only the sheet you want`,
      count: sizes.size,
    });
  }

  // Genus, only meaningful for a closed connected manifold.
  const closedManifold = boundary.length === 0 && nonManifold.length === 0 && badVertices === 0 && sizes.size === 1;
  if (closedManifold) {
    const V = nv - unused;
    const chi = V - edges.size + nf;
    if (chi !== 2) {
      const g = (2 - chi) / 2;
      const what = g === 1 ? 'this mesh has a hole through it' : Number.isInteger(g) ? `this mesh has ${g} holes through it` : 'this surface is not orientable';
      problems.push({
        kind: 'genus',
        severity: 'error',
        message: `genus ${g}: ${what} (V - E + F = ${V} - ${edges.size} + ${nf} = ${chi}); tissue-sheet needs a closed surface without holes (genus 0)`,
        count: g,
      });
    }
    // A closed, oriented surface with (next to) no volume inside: its faces lie in one plane or
    // fold onto each other (two coincident sheets). It has no outside to offset a sheet along,
    // and its sphere map is meaningless. The isoperimetric scale A^1.5 (a sphere: V = 0.094 A^1.5)
    // makes the bound independent of units; 1e-6 of it is an aspect ratio of about 1e-5.
    const volume = signedVolume(mesh);
    let area = 0;
    for (const a of faceAreas(mesh)) area += a;
    if (Math.abs(volume) <= 1e-6 * area ** 1.5) {
      problems.push({
        kind: 'flat',
        severity: 'error',
        message: `the mesh encloses no volume (${fmt(volume)} against a surface of ${fmt(area)}): its faces lie in one plane or fold onto each other; tissue-sheet needs a closed surface around a volume`,
        count: nf,
      });
    } else if (inconsistent === 0 && volume < 0) {
      problems.push({
        kind: 'inward',
        severity: 'warning',
        message: 'the triangles are oriented inward (negative enclosed volume); normals will be flipped to point outward',
        count: nf,
      });
    }
  }
  boundary = [];
  nonManifold = [];
  return problems;
}

/** Faces around each vertex, CSR layout: faces[offsets[v] .. offsets[v+1]). */
export function vertexFaces(mesh: TriangleMesh): { offsets: Uint32Array; faces: Uint32Array } {
  const t = mesh.indices;
  const nv = mesh.positions.length / 3;
  const offsets = new Uint32Array(nv + 1);
  for (const i of t) offsets[i + 1]++;
  for (let v = 0; v < nv; v++) offsets[v + 1] += offsets[v];
  const fill = offsets.slice(0, nv);
  const faces = new Uint32Array(t.length);
  for (let i = 0; i < t.length; i++) {
    const v = t[i];
    // Avoid listing a face twice when it repeats this vertex.
    if (i % 3 > 0 && (t[i - 1] === v || (i % 3 === 2 && t[i - 2] === v))) continue;
    faces[fill[v]++] = Math.floor(i / 3);
  }
  // Degenerate faces may leave unused slots; compact them.
  let w = 0;
  const out = new Uint32Array(nv + 1);
  for (let v = 0; v < nv; v++) {
    out[v] = w;
    for (let s = offsets[v]; s < fill[v]; s++) faces[w++] = faces[s];
  }
  out[nv] = w;
  return { offsets: out, faces: faces.subarray(0, w) };
}

/** Throws with all error messages if the mesh is not a closed genus-0 sheet. */
export function assertGenusZero(mesh: TriangleMesh): void {
  const errors = checkMesh(mesh).filter((p) => p.severity === 'error');
  if (errors.length > 0) throw new Error(errors.map((p) => p.message).join('\n'));
}
