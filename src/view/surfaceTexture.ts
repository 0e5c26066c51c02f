/**
 * The texture of a plane's or tube's surface in the 3D view: its exact cells drawn on a canvas
 * (smooth borders, not the label image's texels), or the picture the pipeline's worker already
 * drew (workerPictures.ts): a finished one, or a drag's draft of one pixel per texel.
 */
import * as THREE from 'three';
import { drawExactCells, drawnByTexels } from './exactCells';
import { paintSurface } from './sideColors';
import type { ViewStack, ViewSurface } from './stack';
import { PICTURE_LAYOUT, workerPicture } from './workerPictures';

export interface SurfacePaint {
  highlightScutoids: boolean;
  selected: number;
}

export function surfaceTexture(stack: ViewStack, surface: ViewSurface, paint: SurfacePaint, maxAnisotropy: number): THREE.Texture {
  const { width, height } = surface.image.grid;
  const picture =
    workerPicture(surface, 'texture', paint) ??
    (drawnByTexels(surface)
      ? new ImageData(paintSurface(surface, { ...paint, valid: stack.valid, scutoid: stack.scutoid }) as Uint8ClampedArray<ArrayBuffer>, width, height)
      : null);
  let texture: THREE.Texture;
  if (picture) texture = new THREE.Texture(picture);
  else {
    const canvas = document.createElement('canvas');
    drawExactCells(canvas, surface, { ...paint, ...PICTURE_LAYOUT.texture(surface), valid: stack.valid, scutoid: stack.scutoid });
    texture = new THREE.CanvasTexture(canvas);
  }
  texture.flipY = false;
  if (picture instanceof ImageData) {
    // A drag's draft (the label image, one texel per pixel): sampled as texels, no mipmaps or
    // anisotropy, which cost a software GPU most of a frame per streamed result.
    texture.magFilter = THREE.NearestFilter;
    texture.minFilter = THREE.LinearFilter;
    texture.generateMipmaps = false;
  } else {
    texture.magFilter = THREE.LinearFilter;
    texture.minFilter = THREE.LinearMipmapLinearFilter;
    texture.anisotropy = Math.min(8, maxAnisotropy);
  }
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.wrapS = stack.result.config.surface.kind === 'tube' ? THREE.RepeatWrapping : THREE.ClampToEdgeWrapping;
  texture.needsUpdate = true;
  return texture;
}
