/**
 * The 3D view of the sheet: every surface of the stack as a mesh textured with its painted label
 * image (tube: coaxial cylinders; plane: parallel sheets) or, on closed surfaces (sphere,
 * ellipsoid, mesh), the triangle mesh of each surface's geometry image (cubeAtlasMesh.ts) with
 * each fragment's cell found exactly, as the nearest of its candidate sites (closedMaterial.ts);
 * orbit controls, per-surface visibility, and a cut (a
 * clipping plane) to see inside. Renders on demand only (no loop), so screenshots are stable and
 * an idle page costs nothing.
 */
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { ViewStack } from './stack';
import type { PlanarConfig } from '../core/config';
import { closedCellAt, closedSurfaceGeometry } from './closedSurfaceObject';
import { closedCellsMaterial, disposeClosedCells, setClosedPaint } from './closedMaterial';
import { sheetBounds, sheetPose, solidPose, type CameraPose, type SheetBounds } from './cameraFit';
import { surfaceTexture } from './surfaceTexture';
import { surfaceGeometry } from './surfaceGeometry';
import { PickOutlines } from './pickOutlines';
import { uploadNextBands } from './bandedTexture';
import { acceleratePicking } from './pickAcceleration';
import type { CellSolid } from './cellSolid';
import { CellSolidDisplay } from './cellSolidMesh';

/** A picked cell: which surface of the stack it was picked on, and its id. */
export interface PickedCell {
  surface: number;
  cell: number;
}

export interface SheetViewOptions {
  highlightScutoids?: boolean;
  background?: string;
}

export class SheetView3D {
  readonly renderer: THREE.WebGLRenderer;
  private readonly scene = new THREE.Scene();
  private readonly camera = new THREE.PerspectiveCamera(35, 1, 1, 1e6);
  private readonly controls: OrbitControls;
  /** Orientation (a tube lies across the view); `inner` centres the sheet at the origin. */
  private readonly group = new THREE.Group();
  private readonly inner = new THREE.Group();
  private readonly meshes: THREE.Mesh[] = [];
  /**
   * Materials are kept from one result to the next (only their textures change): a material's
   * shader program lives as long as a material uses it, and compiling it again on every result
   * stalled the main thread (~60 ms per program on a software GPU).
   */
  private readonly materials: { textured: THREE.MeshBasicMaterial[]; closed: THREE.ShaderMaterial[] } = { textured: [], closed: [] };
  private readonly clip = new THREE.Plane(new THREE.Vector3(0, -1, 0), 0);
  private cutFraction = 0;
  private radius = 1;
  /** The sheet's extent in the view's frame, for the whole-sheet camera fit (cameraFit.ts). */
  private bounds: SheetBounds = { halfSize: new THREE.Vector3(1, 1, 1), radius: 1 };
  private highlight: boolean;
  private selected = -1;
  private readonly raycaster = new THREE.Raycaster();
  private stack: ViewStack | null = null;
  private frame = 0;
  private readonly resizeObserver: ResizeObserver;
  /** The picked cell's solid (cellSolid.ts, cellSolidMesh.ts), in the sheet's frame. */
  private readonly solid: CellSolidDisplay;
  /** The picked cell on planes and tubes: an outline over the pictures (pickOverlay.ts). */
  private readonly outlines: PickOutlines;

  /** Throws when the canvas cannot give a WebGL context (the caller says so in the page). */
  constructor(
    readonly canvas: HTMLCanvasElement,
    options: SheetViewOptions = {},
  ) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.localClippingEnabled = true;
    this.scene.background = new THREE.Color(options.background ?? '#f4f4f0');
    this.highlight = options.highlightScutoids ?? true;
    this.scene.add(this.group);
    this.group.add(this.inner);
    this.solid = new CellSolidDisplay(this.scene, this.camera, this.inner);
    this.outlines = new PickOutlines(this.renderer, this.clip);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.requestRender());
    // Arrow keys pan when the canvas has the focus (it is focusable: tabindex 0).
    if (!canvas.hasAttribute('tabindex')) canvas.tabIndex = 0;
    this.controls.listenToKeyEvents(canvas);
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(canvas);
    this.resize();
  }

  /**
   * Shows a new result. The camera is refitted on every change of geometry (the surface, the
   * thickness, the surface ratio, the layers), so the whole sheet is always in view; a new
   * result of the same geometry (more Lloyd iterations, another seed) keeps the user's view.
   */
  setStack(stack: ViewStack): void {
    const previous = this.stack;
    // The same stack again (a project restoring its view after it was shown): nothing to rebuild.
    if (stack === previous) return;
    this.stack = stack;
    this.rebuild();
    if (!previous || geometryKey(previous) !== geometryKey(stack)) this.fitCamera();
    this.requestRender();
  }

  setHighlightScutoids(on: boolean): void {
    // Unchanged (a project restoring its view): no second repaint of large pictures.
    if (on === this.highlight) return;
    this.highlight = on;
    this.repaint();
  }

  /** Draws cell `id` white on every surface (-1: none). */
  setSelected(id: number): void {
    if (id === this.selected) return;
    this.selected = id;
    if (this.stack?.closed) this.repaint();
    else {
      // Planes and tubes: the cell's outline laid over the pictures, which stay as they are.
      this.outlines.place(this.meshes, this.stack, id);
      this.requestRender();
    }
  }

  /** The picked cell or the stripes changed: closed surfaces take new uniforms, sheets a new picture. */
  private repaint(): void {
    if (this.stack?.closed) for (const material of this.materials.closed) setClosedPaint(material, this.selected, this.highlight);
    else if (this.stack) this.rebuild();
    this.requestRender();
  }

  /** The cell under a point of the canvas (client pixels), on the nearest visible surface. */
  pickCell(clientX: number, clientY: number): PickedCell | null {
    const stack = this.stack;
    if (!stack) return null;
    const box = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - box.left) / box.width) * 2 - 1, -((clientY - box.top) / box.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.camera);
    const hits = this.raycaster.intersectObjects(
      this.meshes.filter((m) => m.visible),
      false,
    );
    for (const hit of hits) {
      // The cut removes what lies on the far side of its plane: skip those hits.
      if (this.cutFraction > 0 && this.clip.distanceToPoint(hit.point) < 0) continue;
      const index = this.meshes.indexOf(hit.object as THREE.Mesh);
      const surface = stack.surfaces[index];
      if (!surface) continue;
      // A closed surface: the cell its fragment shader draws there; else the label under the uv.
      let cell = closedCellAt(hit);
      if (cell === null) {
        cell = -1;
        if (hit.uv) {
          const { width, height } = surface.image.grid;
          const x = Math.min(width - 1, Math.max(0, Math.floor(hit.uv.x * width)));
          const y = Math.min(height - 1, Math.max(0, Math.floor(hit.uv.y * height)));
          cell = surface.image.labels[y * width + x];
        }
      }
      if (cell >= 0) return { surface: index, cell };
    }
    return null;
  }

  /** Draws cell `id` of the stack on screen as a solid through its surfaces (-1: none); the solid, or null. */
  showCellSolid(id: number): CellSolid | null {
    const solid = this.solid.show(this.stack, id);
    this.requestRender();
    return solid;
  }

  /**
   * Turns the camera to the picked cell's solid: looking at it from outside the sheet (along the
   * tube's or the closed surface's outward direction there; a plane keeps its viewing angle), near
   * enough that the solid fills about two thirds of the view. False when no solid is drawn.
   */
  focusOnSolid(): boolean {
    const bounds = this.solid.bounds();
    if (!bounds || !this.stack) return false;
    const pose = solidPose(this.camera, this.controls.target, this.stack.result.config.surface.kind, bounds);
    this.applyPose({ ...pose, near: Math.min(this.camera.near, pose.near) });
    this.requestRender();
    return true;
  }

  /** Builds the pick hierarchies of the large meshes on screen in idle time (pickAcceleration.ts). */
  acceleratePicking(): void {
    acceleratePicking(this.meshes, (mesh) => this.meshes.includes(mesh));
  }

  /** Visibility of surface `index` of the stack. */
  setSurfaceVisible(index: number, visible: boolean): void {
    const mesh = this.meshes[index];
    if (mesh) mesh.visible = visible;
    this.requestRender();
  }

  /** 0: no cut; 0..1: removes that fraction of the sheet's depth, nearest the viewer first. */
  setCut(fraction: number): void {
    this.cutFraction = Math.max(0, Math.min(1, fraction));
    this.updateClip();
    this.requestRender();
  }

  /** The camera's position and orbit target (a project file keeps them). */
  cameraState(): { position: [number, number, number]; target: [number, number, number] } {
    const p = this.camera.position;
    const t = this.controls.target;
    return { position: [p.x, p.y, p.z], target: [t.x, t.y, t.z] };
  }

  /** Puts the camera back where `cameraState` found it. */
  setCameraState(state: { position: readonly number[]; target: readonly number[] }): void {
    this.camera.position.set(state.position[0], state.position[1], state.position[2]);
    this.controls.target.set(state.target[0], state.target[1], state.target[2]);
    this.controls.update();
    this.updateClip();
    this.requestRender();
  }

  resetCamera(): void {
    this.fitCamera();
    this.requestRender();
  }

  /** Renders now (synchronously), e.g. before reading pixels. */
  renderNow(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.updateClip();
    this.renderer.render(this.scene, this.camera);
    // A large picture still uploading (bandedTexture.ts): its next band in the next frame.
    if (uploadNextBands(this.meshes)) this.requestRender();
  }

  requestRender(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.renderNow();
    });
  }

  toBlob(type = 'image/png'): Promise<Blob> {
    // Every band of a picture still uploading, now: the file shows the whole picture.
    while (uploadNextBands(this.meshes));
    this.renderNow();
    return new Promise((resolve, reject) => this.canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the view could not be encoded'))), type));
  }

  /**
   * The view rendered at `width` x `height` pixels (a figure at a chosen DPI), copied to a new
   * 2D canvas; the on-screen size is restored after. Same camera, so the picture is the view.
   */
  renderAt(width: number, height: number): HTMLCanvasElement {
    const size = this.renderer.getSize(new THREE.Vector2());
    const aspect = this.camera.aspect;
    try {
      this.renderer.setSize(width, height, false);
      this.camera.aspect = width / height;
      this.camera.updateProjectionMatrix();
      this.renderNow();
      const out = document.createElement('canvas');
      out.width = width;
      out.height = height;
      out.getContext('2d')!.drawImage(this.canvas, 0, 0);
      return out;
    } finally {
      this.renderer.setSize(size.x, size.y, false);
      this.camera.aspect = aspect;
      this.camera.updateProjectionMatrix();
      this.renderNow();
    }
  }

  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.resizeObserver.disconnect();
    this.controls.dispose();
    this.clearMeshes();
    for (const material of this.materials.closed) disposeClosedCells(material);
    for (const material of [...this.materials.textured, ...this.materials.closed]) material.dispose();
    this.renderer.dispose();
  }

  private resize(): void {
    const width = Math.max(1, this.canvas.clientWidth);
    const height = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  private clearMeshes(): void {
    for (const mesh of this.meshes) {
      this.inner.remove(mesh);
      this.outlines.clear(mesh);
      mesh.geometry.dispose();
      (mesh.material as THREE.MeshBasicMaterial).map?.dispose();
    }
    this.meshes.length = 0;
  }

  private rebuild(): void {
    const stack = this.stack;
    if (!stack) return;
    const visible = this.meshes.map((m) => m.visible);
    this.clearMeshes();
    const config = stack.result.config;
    const closed = stack.closed;
    for (const surface of stack.surfaces) {
      let mesh: THREE.Mesh;
      if (closed) {
        const material = this.closedMaterial(surface.index);
        mesh = new THREE.Mesh(closedSurfaceGeometry(stack, surface, material), material);
      } else {
        // The picked cell is an overlay (pickOutlines.ts): the picture is drawn without it.
        const paint = { highlightScutoids: this.highlight, selected: -1 };
        const material = this.material('textured', surface.index);
        material.map = surfaceTexture(stack, surface, paint, this.renderer.capabilities.getMaxAnisotropy());
        mesh = new THREE.Mesh(surfaceGeometry((config as PlanarConfig).surface, surface.image.grid, surface.offset), material);
      }
      mesh.name = surface.name;
      mesh.visible = visible[surface.index] ?? true;
      this.meshes.push(mesh);
      this.inner.add(mesh);
    }
    // Centre the sheet at the origin; the tube's axis (z) turned to x, across the view.
    const box = new THREE.Box3();
    for (const mesh of this.meshes) {
      mesh.geometry.computeBoundingBox();
      box.union(mesh.geometry.boundingBox!);
    }
    const centre = box.getCenter(new THREE.Vector3());
    this.inner.position.copy(centre).negate();
    this.group.rotation.set(0, config.surface.kind === 'tube' ? Math.PI / 2 : 0, 0);
    this.radius = Math.max(1, box.getBoundingSphere(new THREE.Sphere()).radius);
    this.bounds = sheetBounds(
      this.meshes.map((mesh) => mesh.geometry),
      box,
      config.surface.kind === 'tube',
    );
    if (!closed) {
      this.outlines.place(this.meshes, stack, this.selected);
      this.outlines.warm(this.meshes[0], this.camera, this.scene);
    }
    this.updateClip();
  }

  /** The kept material of surface `index` (see `materials`). */
  private material(kind: 'textured', index: number): THREE.MeshBasicMaterial {
    const pool = this.materials[kind];
    pool[index] ??= new THREE.MeshBasicMaterial({ side: THREE.DoubleSide, clippingPlanes: [this.clip] });
    return pool[index];
  }

  /** The kept material of closed surface `index`, painted with the view's pick and stripes. */
  private closedMaterial(index: number): THREE.ShaderMaterial {
    const material = (this.materials.closed[index] ??= closedCellsMaterial(this.clip));
    setClosedPaint(material, this.selected, this.highlight);
    return material;
  }

  private fitCamera(): void {
    const pose = sheetPose(this.camera, this.stack?.result.config.surface.kind ?? 'plane', this.stack?.closed ?? false, this.bounds);
    this.applyPose(pose);
    this.camera.far = pose.near * 1000;
    this.camera.updateProjectionMatrix();
  }

  private applyPose(pose: CameraPose): void {
    this.camera.position.copy(pose.position);
    this.camera.near = pose.near;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(pose.target);
    this.controls.update();
  }

  /** The cut plane faces the camera: it removes the near part of the sheet. */
  private updateClip(): void {
    if (this.cutFraction <= 0) {
      this.clip.set(new THREE.Vector3(0, 0, -1), 1e9);
      return;
    }
    const toCamera = this.camera.position.clone().sub(this.controls.target).normalize();
    // Points p with n·p + c >= 0 are kept; n points away from the camera.
    const normal = toCamera.clone().negate();
    const depth = this.radius * (1 - 2 * this.cutFraction);
    this.clip.set(normal, depth);
  }
}

/** What the camera fit depends on: the surface and the sheet's geometry. */
function geometryKey(stack: ViewStack): string {
  const { surface, sheet } = stack.result.config;
  const s = sheet as { thickness: number; surfaceRatio?: number | null; direction: string; layers: number };
  return JSON.stringify([surface, s.thickness, s.surfaceRatio ?? null, s.direction, s.layers]);
}
