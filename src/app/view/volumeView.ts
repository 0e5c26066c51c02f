/**
 * A measured volume in 3D (docs/app.md, "Measure a volume"): its basal and apical surfaces side
 * by side in one canvas (two viewports, one camera, turned together), and the picked cell's own
 * 3D shape in a third. The surfaces use the model's legend: each cell flat in the colour of its
 * number of sides on that surface, scutoids striped dark, cells left out of the statistics faded,
 * the picked cell white; while a cell is picked, cells that are neither it nor its neighbours on
 * that surface are darkened, so its neighbours on both sides stand out.
 *
 * Colours live in a small per-cell texture (one texel per cell), so picking repaints only it;
 * the triangles (built in the worker, volumeSurfaces.ts) are uploaded once.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { VolumeMeasuredResult } from '../../core/measure';
import { RGB, SELECTED_RGB, sideColorIndex } from '../../view/sideColors';
import type { CellShape, DrawnSurface } from '../../view/volumeSurfaces';

const TEXTURE_WIDTH = 1024;

const vertexShader = /* glsl */ `
  in float cell;
  flat out int vCell;
  out vec3 vWorld;
  void main() {
    vCell = int(cell + 0.5);
    vec4 world = modelMatrix * vec4(position, 1.0);
    vWorld = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;
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
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    float light = 0.55 + 0.45 * abs(dot(n, normalize(cameraPosition - vWorld)));
    outColor = vec4(rgb * light, 1.0);
  }`;

const shapeFragment = /* glsl */ `
  in vec3 vWorld;
  out vec4 outColor;
  void main() {
    vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    float light = 0.35 + 0.65 * abs(dot(n, normalize(cameraPosition - vWorld)));
    outColor = vec4(vec3(0.93, 0.9, 0.82) * light, 1.0);
  }`;

const shapeVertex = /* glsl */ `
  out vec3 vWorld;
  void main() {
    vec4 world = modelMatrix * vec4(position, 1.0);
    vWorld = world.xyz;
    gl_Position = projectionMatrix * viewMatrix * world;
  }`;

interface Side {
  readonly surface: DrawnSurface;
  readonly mesh: THREE.Mesh;
  readonly texture: THREE.DataTexture;
}

export class VolumeView {
  readonly canvas: HTMLCanvasElement;
  private readonly renderer: THREE.WebGLRenderer;
  private readonly camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1e6);
  private readonly shapeCamera = new THREE.PerspectiveCamera(35, 1, 0.01, 1e6);
  private readonly controls: OrbitControls;
  private readonly scenes = [new THREE.Scene(), new THREE.Scene(), new THREE.Scene()];
  private sides: Side[] = [];
  private shape: THREE.Mesh | null = null;
  private shapeRadius = 1;
  private result: VolumeMeasuredResult | null = null;
  private selected = -1;
  private frame = 0;
  private readonly raycaster = new THREE.Raycaster();

  /** Throws when the canvas cannot give a WebGL2 context (the caller says so in the page). */
  constructor(container: HTMLElement) {
    this.canvas = document.createElement('canvas');
    this.canvas.id = 'volume-canvas';
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    container.append(this.canvas);
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: false, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setScissorTest(true);
    for (const scene of this.scenes) scene.background = new THREE.Color('#f4f4f0');
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.addEventListener('change', () => this.requestRender());
    new ResizeObserver(() => this.resize()).observe(this.canvas);
  }

  /** Shows a measured volume's surfaces (basal, apical), fitting the camera to the tissue. */
  show(result: VolumeMeasuredResult, surfaces: DrawnSurface[]): void {
    this.clear();
    this.result = result;
    this.selected = -1;
    const bounds = new THREE.Box3();
    this.sides = surfaces.map((surface, k) => {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(surface.positions, 3));
      const cells = new Float32Array(surface.positions.length / 3);
      for (let t = 0; t < surface.cells.length; t++) cells[3 * t] = cells[3 * t + 1] = cells[3 * t + 2] = surface.cells[t];
      geometry.setAttribute('cell', new THREE.BufferAttribute(cells, 1));
      geometry.computeBoundingBox();
      geometry.computeBoundingSphere();
      bounds.union(geometry.boundingBox!);
      const rows = Math.max(1, Math.ceil(result.cells.length / TEXTURE_WIDTH));
      const texture = new THREE.DataTexture(new Uint8Array(TEXTURE_WIDTH * rows * 4), TEXTURE_WIDTH, rows, THREE.RGBAFormat);
      const material = new THREE.ShaderMaterial({
        glslVersion: THREE.GLSL3,
        vertexShader,
        fragmentShader,
        uniforms: { colors: { value: texture }, stripe: { value: 1 } },
        side: THREE.DoubleSide,
      });
      const mesh = new THREE.Mesh(geometry, material);
      this.scenes[k].add(mesh);
      return { surface, mesh, texture };
    });
    const centre = bounds.getCenter(new THREE.Vector3());
    const radius = Math.max(1e-6, bounds.getSize(new THREE.Vector3()).length() / 2);
    // Stripes about a quarter of a mean cell across on the basal surface.
    const basal = result.inputs.layers[0];
    const stripe = Math.sqrt(basal.area / Math.max(1, basal.cells)) / 4;
    for (const side of this.sides) (side.mesh.material as THREE.ShaderMaterial).uniforms.stripe.value = stripe;
    this.camera.position.copy(centre).add(new THREE.Vector3(0.3, -1, 0.6).normalize().multiplyScalar(radius * 3.2));
    this.camera.up.set(0, 0, 1);
    this.controls.target.copy(centre);
    this.controls.update();
    this.repaint();
    this.canvas.setAttribute(
      'aria-label',
      `measured volume in 3D: basal surface (left), apical surface (middle), picked cell (right); ${result.cells.length} cells; drag to turn, click a cell to pick it`,
    );
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
      (this.shape.material as THREE.Material).dispose();
      this.shape = null;
    }
    if (shape && shape.indices.length > 0) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(shape.positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(shape.indices, 1));
      geometry.computeBoundingSphere();
      this.shapeRadius = Math.max(1e-6, geometry.boundingSphere!.radius);
      this.shape = new THREE.Mesh(
        geometry,
        new THREE.ShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader: shapeVertex, fragmentShader: shapeFragment, side: THREE.DoubleSide }),
      );
      this.scenes[2].add(this.shape);
    }
    this.requestRender();
  }

  /** The cell (0-based id) under a click, on the surface of the viewport clicked; -1 none. */
  pick(clientX: number, clientY: number): { cell: number; surface: number } | null {
    const rect = this.canvas.getBoundingClientRect();
    const third = rect.width / 3;
    const k = Math.floor((clientX - rect.left) / third);
    if (k < 0 || k > 1 || !this.sides[k]) return null;
    const x = ((clientX - rect.left - k * third) / third) * 2 - 1;
    const y = -((clientY - rect.top) / rect.height) * 2 + 1;
    this.raycaster.setFromCamera(new THREE.Vector2(x, y), this.camera);
    const hit = this.raycaster.intersectObject(this.sides[k].mesh, false)[0];
    if (!hit || hit.faceIndex === undefined || hit.faceIndex === null) return null;
    return { cell: this.sides[k].surface.cells[hit.faceIndex], surface: k };
  }

  /** The canvas as a PNG (what is drawn). */
  async png(): Promise<Blob> {
    this.render();
    return new Promise((resolve, reject) => this.canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('the 3D view could not be saved'))), 'image/png'));
  }

  private repaint(): void {
    const result = this.result;
    if (!result) return;
    const picked = this.selected >= 0 ? result.cells[this.selected] : null;
    this.sides.forEach((side, k) => {
      const data = side.texture.image.data as Uint8Array;
      const near = picked ? new Set(picked.neighbours[k]) : null;
      for (const cell of result.cells) {
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
    this.requestRender();
  }

  private requestRender(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.render();
    });
  }

  private render(): void {
    const width = this.canvas.clientWidth || 900;
    const height = this.canvas.clientHeight || 300;
    const third = Math.floor(width / 3);
    this.camera.aspect = third / height;
    this.camera.updateProjectionMatrix();
    // The shape's camera looks the same way as the tissue's, from its own distance.
    if (this.shape) {
      const centre = this.shape.geometry.boundingSphere!.center;
      const direction = this.camera.position.clone().sub(this.controls.target).normalize();
      this.shapeCamera.position.copy(centre).addScaledVector(direction, this.shapeRadius * 3.5);
      this.shapeCamera.up.copy(this.camera.up);
      this.shapeCamera.lookAt(centre);
      this.shapeCamera.aspect = this.camera.aspect;
      this.shapeCamera.updateProjectionMatrix();
    }
    for (let k = 0; k < 3; k++) {
      this.renderer.setViewport(k * third, 0, third, height);
      this.renderer.setScissor(k * third, 0, third, height);
      this.renderer.render(this.scenes[k], k === 2 ? this.shapeCamera : this.camera);
    }
  }

  private resize(): void {
    const width = this.canvas.clientWidth;
    const height = this.canvas.clientHeight;
    if (width > 0 && height > 0) this.renderer.setSize(width, height, false);
    this.requestRender();
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
