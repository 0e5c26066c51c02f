import { describe, expect, it } from 'vitest';
import { assertGenusZero, checkMesh, meshTopology } from '../../src/core/mesh/check';
import { flipOrientation, icosphere, mapVertices, openSphere, selectFaces, torusMesh } from '../../src/core/mesh/generate';
import { mergeMeshes, type TriangleMesh } from '../../src/core/mesh/types';
import { GENUS_ZERO_SHIPPED, loadShipped } from './helpers';

const sphere = icosphere(4);
const withFaces = (m: TriangleMesh, extra: number[]): TriangleMesh => ({ positions: m.positions, indices: Uint32Array.from([...m.indices, ...extra]) });
const kinds = (m: TriangleMesh) => checkMesh(m).map((p) => p.kind);
const message = (m: TriangleMesh, kind: string) => checkMesh(m).find((p) => p.kind === kind)?.message ?? '';

describe('checkMesh', () => {
  it('a closed icosphere and the shipped genus-0 meshes have no problem', () => {
    expect(checkMesh(sphere)).toEqual([]);
    for (const f of GENUS_ZERO_SHIPPED) expect(checkMesh(loadShipped(f)), f).toEqual([]);
    expect(meshTopology(sphere).eulerCharacteristic).toBe(2);
  });

  it('open mesh: counts boundary edges and holes, names the first edge and its position', () => {
    const open = loadShipped('open-sphere.ply');
    const m = message(open, 'open');
    const boundary = meshTopology(open).boundaryEdges;
    expect(boundary).toBeGreaterThan(0);
    expect(m).toContain(`not closed: ${boundary} boundary edges`);
    expect(m).toContain('1 hole');
    expect(m).toMatch(/first joins vertices \d+ \(.+\) and \d+ \(.+\)/);
    // Two holes.
    const two = openSphere(6, 0.5);
    const p = two.positions,
      t = two.indices;
    const cut = selectFaces(two, (f) => p[3 * t[3 * f] + 2] > -0.9); // a second hole at the south pole
    expect(message(cut, 'open')).toMatch(/forming 2 holes/);
  });

  it('non-manifold edge: an extra fin triangle on an existing edge', () => {
    const apex = mapVertices({ positions: new Float32Array([0, 0, 3]), indices: new Uint32Array() }, (q) => q);
    const m = mergeMeshes(sphere, apex);
    const nv = sphere.positions.length / 3;
    const [a, b] = [sphere.indices[0], sphere.indices[1]];
    const fin = withFaces(m, [a, b, nv]);
    expect(kinds(fin)).toContain('non-manifold-edge');
    expect(message(fin, 'non-manifold-edge')).toMatch(new RegExp(`edge ${Math.min(a, b)}-${Math.max(a, b)} .* used by 3 faces`));
  });

  it('non-manifold vertex: two tetrahedra touching at one vertex', () => {
    const tet = (dx: number): TriangleMesh => ({
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1].map((x, k) => (k % 3 === 0 ? x * Math.sign(dx || 1) : x))),
      indices: new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]),
    });
    const both = mergeMeshes(tet(1), tet(-1));
    // Share vertex 0 (the origin): re-point the second tetrahedron's origin to vertex 0.
    const idx = both.indices.map((v) => (v === 4 ? 0 : v));
    const m = { positions: both.positions, indices: idx };
    expect(message(m, 'non-manifold-vertex')).toMatch(/1 non-manifold vertices .* vertex 0 at \(0, 0, 0\)/);
  });

  it('degenerate faces: repeated vertex and zero area', () => {
    expect(message(withFaces(sphere, [5, 5, 7]), 'degenerate-face')).toMatch(/1 degenerate faces repeat a vertex \(first: face 320 = \(5, 5, 7\)/);
    const nv = sphere.positions.length / 3;
    const line = mergeMeshes(sphere, { positions: new Float32Array([0, 0, 0, 1, 1, 1, 2, 2, 2]), indices: new Uint32Array() });
    const m = withFaces(line, [nv, nv + 1, nv + 2]);
    expect(message(m, 'degenerate-face')).toMatch(/zero area \(collinear vertices; first: face 320/);
  });

  it('duplicate face (any vertex order)', () => {
    const [a, b, c] = sphere.indices.slice(30, 33);
    const m = withFaces(sphere, [c, a, b]);
    expect(message(m, 'duplicate-face')).toMatch(/1 duplicate faces \(first: faces 10 and 320/);
  });

  it('inconsistent orientation: one flipped triangle', () => {
    const t = sphere.indices.slice();
    [t[4], t[5]] = [t[5], t[4]];
    const m = message({ positions: sphere.positions, indices: t }, 'orientation');
    expect(m).toMatch(/inconsistent orientation: 3 edges/);
  });

  it('inward orientation is a warning only', () => {
    const p = checkMesh(flipOrientation(sphere));
    expect(p.map((x) => [x.kind, x.severity])).toEqual([['inward', 'warning']]);
    expect(() => assertGenusZero(flipOrientation(sphere))).not.toThrow();
  });

  it('a closed surface that encloses no volume: a tetrahedron flattened into its plane', () => {
    // Closed, manifold, consistently oriented, genus 0, no degenerate face: only its volume is wrong.
    const flat = { positions: new Float32Array([1, 1, 0, -1, -1, 0, -1, 1, 0, 1, -1, 0]), indices: new Uint32Array([0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2]) };
    expect(checkMesh(flat).map((x) => [x.kind, x.severity])).toEqual([['flat', 'error']]);
    expect(message(flat, 'flat')).toMatch(/^the mesh encloses no volume \(0 against a surface of 8\): its faces lie in one plane/);
    expect(() => assertGenusZero(flat)).toThrow(/encloses no volume/);
    // The same tetrahedron with its apex lifted is fine.
    const lifted = { ...flat, positions: new Float32Array([1, 1, 0, -1, -1, 0, -1, 1, 1, 1, -1, 1]) };
    expect(checkMesh(lifted).filter((x) => x.severity === 'error')).toEqual([]);
  });

  it('torus: genus 1 from the Euler characteristic', () => {
    const torus = loadShipped('torus.ply');
    const p = checkMesh(torus);
    expect(p.map((x) => x.kind)).toEqual(['genus']);
    expect(p[0].message).toMatch(
      /^genus 1: this mesh has a hole through it \(V - E \+ F = \d+ - \d+ \+ \d+ = 0\); tissue-sheet needs a closed surface without holes \(genus 0\)$/,
    );
    // Genus 2 from two tori joined? Two components instead: genus is not reported then.
    const two = mergeMeshes(torusMesh(1, 0.3, 12, 8), icosphere(2));
    expect(kinds(two)).toEqual(['components']);
  });

  it('two components: says how many and their sizes', () => {
    const m = mergeMeshes(
      icosphere(4),
      mapVertices(icosphere(2), ([x, y, z]) => [x + 5, y, z]),
    );
    expect(message(m, 'components')).toMatch(/2 separate connected components \(faces per component: 320, 80\)/);
    expect(() => assertGenusZero(m)).toThrow(/2 separate connected components/);
  });

  it('empty mesh', () => {
    expect(kinds({ positions: new Float32Array(), indices: new Uint32Array() })).toEqual(['empty']);
  });
});
