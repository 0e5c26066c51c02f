import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig, type MeshSurface } from '../../src/core/config';
import { checkMeshExtent, MESH_EXTENT_UM, prepareMesh } from '../../src/run/closedMesh';

/** An icosahedron of circumradius `r` as OBJ text; `flipped`: every face wound the other way (normals inward). */
function icosahedron(r: number, flipped = false): string {
  const t = (1 + Math.sqrt(5)) / 2;
  const s = r / Math.hypot(1, t);
  const v = [
    [-1, t, 0],
    [1, t, 0],
    [-1, -t, 0],
    [1, -t, 0],
    [0, -1, t],
    [0, 1, t],
    [0, -1, -t],
    [0, 1, -t],
    [t, 0, -1],
    [t, 0, 1],
    [-t, 0, -1],
    [-t, 0, 1],
  ];
  const f = [
    [0, 11, 5],
    [0, 5, 1],
    [0, 1, 7],
    [0, 7, 10],
    [0, 10, 11],
    [1, 5, 9],
    [5, 11, 4],
    [11, 10, 2],
    [10, 7, 6],
    [7, 1, 8],
    [3, 9, 4],
    [3, 4, 2],
    [3, 2, 6],
    [3, 6, 8],
    [3, 8, 9],
    [4, 9, 5],
    [2, 4, 11],
    [6, 2, 10],
    [8, 6, 7],
    [9, 8, 1],
  ];
  return [
    ...v.map((p) => `v ${p.map((c) => c * s).join(' ')}`),
    ...f.map(([a, b, c]) => (flipped ? `f ${a + 1} ${c + 1} ${b + 1}` : `f ${a + 1} ${b + 1} ${c + 1}`)),
  ].join('\n');
}

/** Each face as its three vertex positions in winding order, from its smallest; sorted. */
function orientedTriangles(mesh: { positions: Float32Array; indices: Uint32Array }): string[] {
  const at = (v: number) => Array.from(mesh.positions.subarray(3 * v, 3 * v + 3)).join(',');
  const faces: string[] = [];
  for (let f = 0; f < mesh.indices.length; f += 3) {
    const corners = [0, 1, 2].map((k) => at(mesh.indices[f + k]));
    const first = corners.indexOf([...corners].sort()[0]);
    faces.push([0, 1, 2].map((k) => corners[(first + k) % 3]).join(' '));
  }
  return faces.sort();
}

function reversed(indices: Uint32Array): Uint32Array {
  const t = indices.slice();
  for (let f = 0; f < t.length; f += 3) [t[f + 1], t[f + 2]] = [t[f + 2], t[f + 1]];
  return t;
}

function surface(scale = 1): MeshSurface {
  const config = validateConfig({ surface: { kind: 'mesh', src: 'ico.obj', scale }, cells: 20 });
  return config.surface as MeshSurface;
}

describe('prepareMesh: orientation and size (issue 26)', () => {
  it('a mesh with flipped normals is re-oriented and says so; the prepared surface is the outward one', () => {
    const outward = prepareMesh({ data: icosahedron(50), name: 'ico.obj' }, surface(), 8);
    const inward = prepareMesh({ data: icosahedron(50, true), name: 'ico.obj' }, surface(), 8);
    expect(outward.reoriented).toBeNull();
    expect(inward.reoriented).toMatch(/^ico\.obj: the triangles were oriented inward .* flipped to point outward/);
    // Flipping an inward file's faces gives back the outward file's oriented triangles (the
    // parser numbers vertices by first use, so compared as positions in winding order).
    expect(orientedTriangles(inward.mesh)).toEqual(orientedTriangles(outward.mesh));
    expect(orientedTriangles(inward.mesh)).not.toEqual(orientedTriangles({ ...outward.mesh, indices: reversed(outward.mesh.indices) }));
  });

  it('a mesh scaled to 1e30 is refused for its size, with the scale that would fit', () => {
    let error: unknown = null;
    try {
      prepareMesh({ data: icosahedron(1e30), name: 'ico.obj' }, surface(), 8);
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(ConfigError);
    expect((error as ConfigError).field).toBe('surface.src');
    // The icosahedron's bounding box is 2 t / hypot(1, t) ≈ 1.701 of its circumradius across.
    const across = (2e30 * ((1 + Math.sqrt(5)) / 2)) / Math.hypot(1, (1 + Math.sqrt(5)) / 2);
    expect((error as Error).message).toContain(`the mesh is ${across.toExponential(2)} µm across after surface.scale 1`);
    expect((error as Error).message).toMatch(/set surface\.scale to about \S+ for a 100 µm sheet/);
    expect((error as Error).message).not.toMatch(/minSpacing/);
  });

  it('the size limits are inclusive and a tiny or overflowing mesh is refused too', () => {
    const box = (size: number) => ({ positions: new Float32Array([0, 0, 0, size, 0, 0, 0, size, 0]), indices: new Uint32Array([0, 1, 2]) });
    expect(() => checkMeshExtent(box(MESH_EXTENT_UM.max), 'a', 1)).not.toThrow();
    expect(() => checkMeshExtent(box(100), 'a', 1)).not.toThrow();
    expect(() => checkMeshExtent(box(MESH_EXTENT_UM.max * 2), 'a', 1)).toThrow(/2\.00e\+6 µm across/);
    expect(() => checkMeshExtent(box(1e-5), 'a', 1)).toThrow(/1\.00e-5 µm across/);
    expect(() => checkMeshExtent(box(Infinity), 'a', 1)).toThrow(/of no finite size/);
  });
});
