/**
 * Draws a measured volume (docs/app.md, "Measure a volume") into a canvas that may be an
 * OffscreenCanvas in a worker (volumeRenderWorker.ts): the basal and apical surfaces side by side
 * (two viewports, one orbit camera) and the picked cell's 3D shape in a third; and in a second
 * row, the model of the same geometry (its basal and apical surfaces, same legend, same camera,
 * and a picked model cell's own triangles on both). The layout shows the tissue's row, the
 * model's, or both (tissue above). No DOM.
 *
 * The surfaces use the model's legend: each cell flat in the colour of its number of sides on
 * that surface, scutoids striped dark, cells left out of the statistics faded, the picked cell
 * white; while a cell is picked, cells that are neither it nor its neighbours on that surface are
 * darkened, so its neighbours on both sides stand out. Colours live in a small per-cell texture
 * (one texel per cell): picking repaints only it; the triangles are uploaded once.
 */
import * as THREE from 'three';
import { RGB, SELECTED_RGB, sideColorIndex } from './sideColors';
import type { CellShape, DrawnSurface } from './volumeSurfaces';

const TEXTURE_WIDTH = 1024;

/** What the renderer needs of each measured cell (the result's record, trimmed). */
export interface DrawnCell {
  readonly id: number;
  readonly label: number;
  readonly valid: boolean;
  readonly scutoid: boolean;
  /** Sides on basal, apical. */
  readonly sides: readonly number[];
  /** Neighbour labels on basal, apical. */
  readonly neighbours: readonly (readonly number[])[];
}

/** The orbit camera: looking at `target` from `distance`, turned by azimuth and elevation (radians, z up). */
export interface Orbit {
  readonly target: [number, number, number];
  readonly distance: number;
  readonly azimuth: number;
  readonly elevation: number;
}

/** GLSL: the vertex's world position into vWorld, and its clip position. */
const worldPosition = /* glsl */ `
    vec4 world = modelMatrix * vec4(position, 1.0);
    vWorld = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;`;

/** GLSL: the facing of the triangle's own normal to the camera, 0 to 1 (flat shading without lights). */
const facing = /* glsl */ `abs(dot(normalize(cross(dFdx(vWorld), dFdy(vWorld))), normalize(cameraPosition - vWorld)))`;

const vertexShader = /* glsl */ `
  in float cell;
  flat out int vCell;
  out vec3 vWorld;
  void main() {
    vCell = int(cell + 0.5);${worldPosition}
  }`;

const fragmentShader = /* glsl */ `
  uniform sampler2D colors;
  uniform float stripe;
  flat in int vCell;
  in vec3 vWorld;
  out vec4 outColor;
  void main() {
    vec4 c = texelFetch(colors, ivec2(vCell % ${TEXTURE_WIDTH}, vCell / ${TEXTURE_WIDTH}), 0);
    vec3 rgb = c.rgb;
    // Scutoids: dark stripes across the surface (alpha 1), as the model's views stripe them.
    if (c.a > 0.5 && fract((vWorld.x + vWorld.y + vWorld.z) / stripe) < 0.25) rgb = vec3(0.08);
    // Flat shading from the triangle's own normal: the surface's relief without lights.
    float light = 0.55 + 0.45 * ${facing};
    outColor = vec4(rgb * light, 1.0);
  }`;

const shapeVertex = /* glsl */ `
  out vec3 vWorld;
  void main() {${worldPosition}
  }`;

const shapeFragment = /* glsl */ `
  in vec3 vWorld;
  out vec4 outColor;
  void main() {
    float light = 0.35 + 0.65 * ${facing};
    outColor = vec4(vec3(0.93, 0.9, 0.82) * light, 1.0);
  }`;

interface Side {
  readonly surface: DrawnSurface;
  readonly mesh: THREE.Mesh;
  readonly texture: THREE.DataTexture;
}

/** Which rows the canvas shows: the measured tissue, the model of the same geometry, or both (tissue above). */
export type VolumeLayout = 'tissue' | 'model' | 'both';

/** The rows: 0 the measured tissue, 1 the model. */
export type RowName = 'tissue' | 'model';
const ROWS: readonly RowName[] = ['tissue', 'model'];

/** One row of three viewports: basal, apical, and the picked cell. */
class Row {
  readonly scenes = [new THREE.Scene(), new THREE.Scene(), new THREE.Scene()];
  sides: Side[] = [];
  cells: readonly DrawnCell[] = [];
  selected = -1;
  shape: THREE.Mesh | null = null;
  shapeRadius = 1;

  constructor() {
    for (const scene of this.scenes) scene.background = new THREE.Color('#f4f4f0');
  }
}

/** The camera position of an orbit. */
function orbitPosition(orbit: Orbit): [number, number, number] {
  const c = Math.cos(orbit.elevation);
  return [
    orbit.target[0] + orbit.distance * c * Math.cos(orbit.azimuth),
    orbit.target[1] + orbit.distance * c * Math.sin(orbit.azimuth),
    orbit.target[2] + orbit.distance * Math.sin(orbit.elevation),
  ];
}

export class VolumeRenderer {
  private readonly renderer: THREE.WebGLRenderer;
  private readonly camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1e6);
  private readonly shapeCamera = new THREE.PerspectiveCamera(35, 1, 0.01, 1e6);
  private readonly rows = [new Row(), new Row()];
  private readonly shapeMaterial = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: shapeVertex,
    fragmentShader: shapeFragment,
    side: THREE.DoubleSide,
  });
  private readonly raycaster = new THREE.Raycaster();
  private layout: VolumeLayout = 'tissue';
  private orbit: Orbit = { target: [0, 0, 0], distance: 1, azimuth: 0, elevation: 0 };
  private width = 1;
  private height = 1;

  constructor(canvas: HTMLCanvasElement | OffscreenCanvas) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setScissorTest(true);
  }

  setSize(width: number, height: number): void {
    this.width = Math.max(1, Math.round(width));
    this.height = Math.max(1, Math.round(height));
    this.renderer.setSize(this.width, this.height, false);
  }

  /** Shows a measured volume's surfaces (basal, apical), no model yet; returns the orbit that fits the tissue. */
  show(cells: readonly DrawnCell[], surfaces: DrawnSurface[], stripe: number): Orbit {
    this.clear(this.rows[1]);
    this.layout = 'tissue';
    const bounds = this.fill(this.rows[0], cells, surfaces, stripe);
    const centre = bounds.getCenter(new THREE.Vector3());
    const radius = Math.max(1e-6, bounds.getSize(new THREE.Vector3()).length() / 2);
    this.orbit = { target: [centre.x, centre.y, centre.z], distance: radius * 3.2, azimuth: -1.25, elevation: 0.5 };
    return this.orbit;
  }

  /**
   * Shows the model of the same geometry (its basal and apical surfaces, in the volume's
   * coordinates: the tissue's camera frames it too); returns how many cells each surface draws.
   */
  showModel(cells: readonly DrawnCell[], surfaces: DrawnSurface[], stripe: number): number[] {
    this.fill(this.rows[1], cells, surfaces, stripe);
    return surfaces.map((s) => new Set(s.cells).size);
  }

  setLayout(layout: VolumeLayout): void {
    this.layout = layout;
  }

  setOrbit(orbit: Orbit): void {
    this.orbit = orbit;
  }

  /** Cell `id` (0-based) of a row picked: white, its neighbours on each surface kept bright; -1 none. */
  setSelected(row: RowName, id: number): void {
    const r = this.rows[ROWS.indexOf(row)];
    r.selected = id;
    if (row === 'tissue') {
      if (id < 0) this.setShape(null);
    } else this.setModelShape(r, id);
    this.repaint(r);
  }

  /** The picked tissue cell's 3D shape in the tissue row's third viewport (null: none). */
  setShape(shape: CellShape | null): void {
    const row = this.rows[0];
    this.placeShape(row, shape && shape.indices.length > 0 ? this.shapeGeometry(shape.positions, shape.indices) : null);
  }

  /** The cell (0-based id) at canvas point (x, y) in pixels, on the surface of the viewport there; null none. */
  pick(x: number, y: number): { row: RowName; cell: number; surface: number } | null {
    const visible = this.visibleRows();
    const third = this.width / 3;
    const rowHeight = this.height / visible.length;
    const k = Math.floor(x / third);
    const ri = Math.floor(y / rowHeight);
    if (k < 0 || k > 1 || ri < 0 || ri >= visible.length) return null;
    const row = this.rows[visible[ri]];
    if (!row.sides[k]) return null;
    this.placeCameras(rowHeight);
    const ndc = new THREE.Vector2(((x - k * third) / third) * 2 - 1, -((y - ri * rowHeight) / rowHeight) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(row.sides[k].mesh, false)[0];
    if (!hit || hit.faceIndex === undefined || hit.faceIndex === null) return null;
    return { row: ROWS[visible[ri]], cell: row.sides[k].surface.cells[hit.faceIndex], surface: k };
  }

  render(): void {
    const visible = this.visibleRows();
    const rowHeight = Math.floor(this.height / visible.length);
    this.placeCameras(rowHeight);
    const third = Math.floor(this.width / 3);
    visible.forEach((r, ri) => {
      const row = this.rows[r];
      // GL viewports count from the bottom: the first visible row is the top one.
      const y = this.height - (ri + 1) * rowHeight;
      for (let k = 0; k < 3; k++) {
        this.renderer.setViewport(k * third, y, third, rowHeight);
        this.renderer.setScissor(k * third, y, third, rowHeight);
        if (k === 2) this.placeShapeCamera(row);
        this.renderer.render(row.scenes[k], k === 2 ? this.shapeCamera : this.camera);
      }
    });
  }

  private visibleRows(): number[] {
    return this.layout === 'both' ? [0, 1] : this.layout === 'model' ? [1] : [0];
  }

  /** A row's surfaces and per-cell colour textures; returns their bounds. */
  private fill(row: Row, cells: readonly DrawnCell[], surfaces: DrawnSurface[], stripe: number): THREE.Box3 {
    this.clear(row);
    row.cells = cells;
    row.selected = -1;
    const bounds = new THREE.Box3();
    const rows = Math.max(1, Math.ceil(cells.length / TEXTURE_WIDTH));
    row.sides = surfaces.map((surface, k) => {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions, 3));
      const ids = new Float32Array(surface.positions.length / 3);
      for (let t = 0; t < surface.cells.length; t++) ids[3 * t] = ids[3 * t + 1] = ids[3 * t + 2] = surface.cells[t];
      geometry.setAttribute('cell', new THREE.BufferAttribute(ids, 1));
      geometry.computeBoundingBox();
      geometry.computeBoundingSphere();
      bounds.union(geometry.boundingBox!);
      const texture = new THREE.DataTexture(new Uint8Array(TEXTURE_WIDTH * rows * 4), TEXTURE_WIDTH, rows, THREE.RGBAFormat);
      const material = new THREE.ShaderMaterial({
        glslVersion: THREE.GLSL3,
        vertexShader,
        fragmentShader,
        uniforms: { colors: { value: texture }, stripe: { value: stripe } },
        side: THREE.DoubleSide,
      });
      const mesh = new THREE.Mesh(geometry, material);
      row.scenes[k].add(mesh);
      return { surface, mesh, texture };
    });
    this.repaint(row);
    return bounds;
  }

  private shapeGeometry(positions: Float32Array, indices: Uint32Array | null): THREE.BufferGeometry {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    if (indices) geometry.setIndex(new THREE.BufferAttribute(indices, 1));
    geometry.computeBoundingSphere();
    return geometry;
  }

  /** A picked model cell's "shape": its own triangles on both of the model's surfaces, together. */
  private setModelShape(row: Row, id: number): void {
    if (id < 0) return this.placeShape(row, null);
    let count = 0;
    for (const side of row.sides) for (const c of side.surface.cells) if (c === id) count++;
    const positions = new Float32Array(9 * count);
    let o = 0;
    for (const side of row.sides) {
      const { cells, positions: p } = side.surface;
      for (let t = 0; t < cells.length; t++) {
        if (cells[t] !== id) continue;
        positions.set(p.subarray(9 * t, 9 * t + 9), o);
        o += 9;
      }
    }
    this.placeShape(row, count > 0 ? this.shapeGeometry(positions, null) : null);
  }

  private placeShape(row: Row, geometry: THREE.BufferGeometry | null): void {
    if (row.shape) {
      row.scenes[2].remove(row.shape);
      row.shape.geometry.dispose();
      row.shape = null;
    }
    if (!geometry) return;
    row.shapeRadius = Math.max(1e-6, geometry.boundingSphere!.radius);
    row.shape = new THREE.Mesh(geometry, this.shapeMaterial);
    row.scenes[2].add(row.shape);
  }

  private placeCameras(rowHeight: number): void {
    const aspect = Math.floor(this.width / 3) / Math.max(1, rowHeight);
    const [x, y, z] = orbitPosition(this.orbit);
    this.camera.position.set(x, y, z);
    this.camera.up.set(0, 0, 1);
    this.camera.lookAt(...this.orbit.target);
    this.camera.aspect = aspect;
    this.camera.updateProjectionMatrix();
    this.camera.updateMatrixWorld();
    this.shapeCamera.aspect = aspect;
  }

  /** The shape's camera looks the same way as the surfaces', from its own distance. */
  private placeShapeCamera(row: Row): void {
    if (!row.shape) return;
    const centre = row.shape.geometry.boundingSphere!.center;
    const direction = this.camera.position
      .clone()
      .sub(new THREE.Vector3(...this.orbit.target))
      .normalize();
    this.shapeCamera.position.copy(centre).addScaledVector(direction, row.shapeRadius * 3.5);
    this.shapeCamera.up.set(0, 0, 1);
    this.shapeCamera.lookAt(centre);
    this.shapeCamera.updateProjectionMatrix();
  }

  private repaint(row: Row): void {
    const picked = row.selected >= 0 ? row.cells[row.selected] : null;
    row.sides.forEach((side, k) => {
      const data = side.texture.image.data as Uint8Array;
      const near = picked ? new Set(picked.neighbours[k]) : null;
      for (const cell of row.cells) {
        let [r, g, b] = RGB[sideColorIndex(cell.sides[k] ?? 0)];
        if (!cell.valid) [r, g, b] = [(r + 470) / 3, (g + 470) / 3, (b + 470) / 3];
        if (cell.id === row.selected) [r, g, b] = SELECTED_RGB;
        else if (near && !near.has(cell.label)) [r, g, b] = [r * 0.35, g * 0.35, b * 0.35];
        const o = 4 * cell.id;
        data[o] = r;
        data[o + 1] = g;
        data[o + 2] = b;
        data[o + 3] = cell.scutoid && cell.id !== row.selected ? 255 : 0;
      }
      side.texture.needsUpdate = true;
    });
  }

  private clear(row: Row): void {
    for (const side of row.sides) {
      side.mesh.parent?.remove(side.mesh);
      side.mesh.geometry.dispose();
      (side.mesh.material as THREE.Material).dispose();
      side.texture.dispose();
    }
    row.sides = [];
    row.cells = [];
    row.selected = -1;
    this.placeShape(row, null);
  }
}
