/**
 * Draws a measured volume (docs/app.md, "Measure a volume") into a canvas that may be an
 * OffscreenCanvas in a worker (volumeRenderWorker.ts): the basal and apical surfaces side by side
 * (two viewports, one orbit camera) and the picked cell's 3D shape in a third. No DOM.
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

/** The camera position of an orbit. */
export function orbitPosition(orbit: Orbit): [number, number, number] {
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
  private readonly scenes = [new THREE.Scene(), new THREE.Scene(), new THREE.Scene()];
  private readonly shapeMaterial = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    vertexShader: shapeVertex,
    fragmentShader: shapeFragment,
    side: THREE.DoubleSide,
  });
  private readonly raycaster = new THREE.Raycaster();
  private sides: Side[] = [];
  private cells: readonly DrawnCell[] = [];
  private shape: THREE.Mesh | null = null;
  private shapeRadius = 1;
  private selected = -1;
  private orbit: Orbit = { target: [0, 0, 0], distance: 1, azimuth: 0, elevation: 0 };
  private width = 1;
  private height = 1;

  constructor(canvas: HTMLCanvasElement | OffscreenCanvas) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setScissorTest(true);
    for (const scene of this.scenes) scene.background = new THREE.Color('#f4f4f0');
  }

  setSize(width: number, height: number): void {
    this.width = Math.max(1, Math.round(width));
    this.height = Math.max(1, Math.round(height));
    this.renderer.setSize(this.width, this.height, false);
  }

  /** Shows a measured volume's surfaces (basal, apical); returns the orbit that fits the tissue. */
  show(cells: readonly DrawnCell[], surfaces: DrawnSurface[], stripe: number): Orbit {
    this.clear();
    this.cells = cells;
    this.selected = -1;
    const bounds = new THREE.Box3();
    const rows = Math.max(1, Math.ceil(cells.length / TEXTURE_WIDTH));
    this.sides = surfaces.map((surface, k) => {
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
      this.scenes[k].add(mesh);
      return { surface, mesh, texture };
    });
    const centre = bounds.getCenter(new THREE.Vector3());
    const radius = Math.max(1e-6, bounds.getSize(new THREE.Vector3()).length() / 2);
    this.orbit = { target: [centre.x, centre.y, centre.z], distance: radius * 3.2, azimuth: -1.25, elevation: 0.5 };
    this.repaint();
    return this.orbit;
  }

  setOrbit(orbit: Orbit): void {
    this.orbit = orbit;
  }

  /** Cell `id` (0-based) picked: white, its neighbours on each surface kept bright; -1 none. */
  setSelected(id: number): void {
    this.selected = id;
    if (id < 0) this.setShape(null);
    this.repaint();
  }

  /** The picked cell's 3D shape in the third viewport (null: none). */
  setShape(shape: CellShape | null): void {
    if (this.shape) {
      this.scenes[2].remove(this.shape);
      this.shape.geometry.dispose();
      this.shape = null;
    }
    if (shape && shape.indices.length > 0) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(shape.positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(shape.indices, 1));
      geometry.computeBoundingSphere();
      this.shapeRadius = Math.max(1e-6, geometry.boundingSphere!.radius);
      this.shape = new THREE.Mesh(geometry, this.shapeMaterial);
      this.scenes[2].add(this.shape);
    }
  }

  /** The cell (0-based id) at canvas point (x, y) in pixels, on the surface of the viewport there; null none. */
  pick(x: number, y: number): { cell: number; surface: number } | null {
    const third = this.width / 3;
    const k = Math.floor(x / third);
    if (k < 0 || k > 1 || !this.sides[k]) return null;
    this.placeCameras();
    const ndc = new THREE.Vector2(((x - k * third) / third) * 2 - 1, -(y / this.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(this.sides[k].mesh, false)[0];
    if (!hit || hit.faceIndex === undefined || hit.faceIndex === null) return null;
    return { cell: this.sides[k].surface.cells[hit.faceIndex], surface: k };
  }

  render(): void {
    this.placeCameras();
    const third = Math.floor(this.width / 3);
    for (let k = 0; k < 3; k++) {
      this.renderer.setViewport(k * third, 0, third, this.height);
      this.renderer.setScissor(k * third, 0, third, this.height);
      this.renderer.render(this.scenes[k], k === 2 ? this.shapeCamera : this.camera);
    }
  }

  private placeCameras(): void {
    const aspect = Math.floor(this.width / 3) / this.height;
    const [x, y, z] = orbitPosition(this.orbit);
    this.camera.position.set(x, y, z);
    this.camera.up.set(0, 0, 1);
    this.camera.lookAt(...this.orbit.target);
    this.camera.aspect = aspect;
    this.camera.updateProjectionMatrix();
    this.camera.updateMatrixWorld();
    // The shape's camera looks the same way as the tissue's, from its own distance.
    if (this.shape) {
      const centre = this.shape.geometry.boundingSphere!.center;
      const direction = this.camera.position
        .clone()
        .sub(new THREE.Vector3(...this.orbit.target))
        .normalize();
      this.shapeCamera.position.copy(centre).addScaledVector(direction, this.shapeRadius * 3.5);
      this.shapeCamera.up.set(0, 0, 1);
      this.shapeCamera.lookAt(centre);
      this.shapeCamera.aspect = aspect;
      this.shapeCamera.updateProjectionMatrix();
    }
  }

  private repaint(): void {
    const picked = this.selected >= 0 ? this.cells[this.selected] : null;
    this.sides.forEach((side, k) => {
      const data = side.texture.image.data as Uint8Array;
      const near = picked ? new Set(picked.neighbours[k]) : null;
      for (const cell of this.cells) {
        let [r, g, b] = RGB[sideColorIndex(cell.sides[k] ?? 0)];
        if (!cell.valid) [r, g, b] = [(r + 470) / 3, (g + 470) / 3, (b + 470) / 3];
        if (cell.id === this.selected) [r, g, b] = SELECTED_RGB;
        else if (near && !near.has(cell.label)) [r, g, b] = [r * 0.35, g * 0.35, b * 0.35];
        const o = 4 * cell.id;
        data[o] = r;
        data[o + 1] = g;
        data[o + 2] = b;
        data[o + 3] = cell.scutoid && cell.id !== this.selected ? 255 : 0;
      }
      side.texture.needsUpdate = true;
    });
  }

  private clear(): void {
    for (const side of this.sides) {
      side.mesh.parent?.remove(side.mesh);
      side.mesh.geometry.dispose();
      (side.mesh.material as THREE.Material).dispose();
      side.texture.dispose();
    }
    this.sides = [];
    this.setShape(null);
  }
}
