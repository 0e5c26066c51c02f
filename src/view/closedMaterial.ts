/**
 * The material of a closed surface in the 3D view: cells found per fragment (closedCandidates.ts,
 * closedCells.vert/.frag), coloured by their sides on that surface, the picked cell white,
 * scutoids striped, borders one pixel wide, and a fixed light that leaves the lit side exactly
 * in the legend's colours. Per-surface data (sites, cell colours) lives in two small float
 * textures; the picked cell and the stripes are uniforms, so picking a cell redraws without
 * rebuilding anything.
 */
import * as THREE from 'three';
import vertexShader from './closedCells.vert';
import fragmentShader from './closedCells.frag';
import { RGB, SELECTED_RGB, sideColorIndex } from './sideColors';

/** A fixed light (object space, from the default camera's side). */
const LIGHT = new THREE.Vector3(0.35, 0.6, 0.75).normalize();
/**
 * Shading: 1 (the legend's colour exactly) wherever the surface faces the light by at least
 * LIT_FROM (n·l), darker only towards the back, down to SHADE_MIN at n·l = -1, so the shape
 * reads without changing the colours a reader matches to the legend.
 */
const LIT_FROM = 0.2;
const SHADE_MIN = 0.7;
/** Cells per row of the per-cell textures (any count fits: rows are added). */
const TEXTURE_WIDTH = 2048;

/** What one closed surface shows. */
export interface ClosedCellsData {
  /** xyz per cell of this surface's sites (µm, the mesh's object space). */
  sites: Float32Array;
  /** Sides of every cell on this surface. */
  sides: ArrayLike<number>;
  /** 1 for scutoids. */
  scutoid: ArrayLike<number>;
  /** Stripe period (µm): a few triangle edges. */
  stripePeriod: number;
}

function linear(rgb: readonly number[]): THREE.Vector3 {
  const c = new THREE.Color().setRGB(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255, THREE.SRGBColorSpace);
  return new THREE.Vector3(c.r, c.g, c.b);
}

/** A material for closed surfaces; give it a surface with `setClosedCells`. */
export function closedCellsMaterial(clip: THREE.Plane): THREE.ShaderMaterial {
  return new THREE.ShaderMaterial({
    vertexShader,
    fragmentShader,
    side: THREE.DoubleSide,
    clipping: true,
    clippingPlanes: [clip],
    uniforms: {
      sites: { value: null },
      cellColors: { value: null },
      textureWidth: { value: TEXTURE_WIDTH },
      selected: { value: -1 },
      highlight: { value: true },
      stripePeriod: { value: 1 },
      lightDirection: { value: LIGHT.clone() },
      litFrom: { value: LIT_FROM },
      shadeMin: { value: SHADE_MIN },
      selectedColor: { value: linear(SELECTED_RGB) },
      noCellColor: { value: linear([40, 40, 40]) },
    },
  });
}

/** One RGBA float texel per cell, TEXTURE_WIDTH cells per row. */
function cellTexture(count: number, fill: (id: number, out: Float32Array, at: number) => void): THREE.DataTexture {
  const width = Math.max(1, Math.min(TEXTURE_WIDTH, count));
  const height = Math.max(1, Math.ceil(count / TEXTURE_WIDTH));
  const data = new Float32Array(4 * width * height);
  for (let id = 0; id < count; id++) fill(id, data, 4 * id);
  const texture = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  texture.magFilter = texture.minFilter = THREE.NearestFilter;
  texture.generateMipmaps = false;
  texture.needsUpdate = true;
  return texture;
}

/** Puts a surface's sites and cell colours into `material` (the previous textures are freed). */
export function setClosedCells(material: THREE.ShaderMaterial, data: ClosedCellsData): void {
  const u = material.uniforms;
  (u.sites.value as THREE.Texture | null)?.dispose();
  (u.cellColors.value as THREE.Texture | null)?.dispose();
  const count = data.sites.length / 3;
  // The shader indexes rows of TEXTURE_WIDTH cells whatever the row count.
  u.textureWidth.value = Math.max(1, Math.min(TEXTURE_WIDTH, count));
  u.sites.value = cellTexture(count, (id, out, at) => out.set(data.sites.subarray(3 * id, 3 * id + 3), at));
  const palette = RGB.map(linear);
  u.cellColors.value = cellTexture(count, (id, out, at) => {
    const c = palette[sideColorIndex(data.sides[id] ?? 0)];
    out[at] = c.x;
    out[at + 1] = c.y;
    out[at + 2] = c.z;
    out[at + 3] = data.scutoid[id] ? 1 : 0;
  });
  u.stripePeriod.value = Math.max(1e-6, data.stripePeriod);
}

/** The picked cell (-1: none) and whether scutoids are striped: uniforms only, nothing rebuilt. */
export function setClosedPaint(material: THREE.ShaderMaterial, selected: number, highlight: boolean): void {
  material.uniforms.selected.value = selected;
  material.uniforms.highlight.value = highlight;
}

/** Frees a closed material's textures (the material itself is kept by the view). */
export function disposeClosedCells(material: THREE.ShaderMaterial): void {
  (material.uniforms.sites.value as THREE.Texture | null)?.dispose();
  (material.uniforms.cellColors.value as THREE.Texture | null)?.dispose();
  material.uniforms.sites.value = null;
  material.uniforms.cellColors.value = null;
}
