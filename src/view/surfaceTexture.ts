/**
 * The texture of a plane's or tube's surface in the 3D view: its exact cells drawn on a canvas
 * (smooth borders, not the label image's texels), or the picture the pipeline's worker already
 * drew (workerPictures.ts): a finished one, or a drag's draft of one pixel per texel.
 */
import * as THREE from 'three';
import { drawExactCells, drawnByTexels } from './exactCells';
import { paintSurface } from './sideColors';
import type { ViewStack, ViewSurface } from './stack';
import { PICTURE_LAYOUT, workerPicture, workerRgba } from './workerPictures';
import { bandedTexture } from './bandedTexture';

export interface SurfacePaint {
  highlightScutoids: boolean;
  selected: number;
}

export function surfaceTexture(stack: ViewStack, surface: ViewSurface, paint: SurfacePaint, maxAnisotropy: number): THREE.Texture {
  const { width, height } = surface.image.grid;
  // Very many cells: the painted label image (the worker's when it painted one), uploaded a band
  // of rows per frame (bandedTexture.ts).
  const texels = drawnByTexels(surface)
    ? (workerRgba(surface, paint) ?? paintSurface(surface, { ...paint, valid: stack.valid, scutoid: stack.scutoid }))
    : null;
  const picture = texels ?? workerPicture(surface, 'texture', paint);
  let texture: THREE.Texture;
  if (picture instanceof Uint8ClampedArray) texture = bandedTexture(picture, width, height);
  else if (picture) texture = new THREE.Texture(picture);
  else {
    const canvas = document.createElement('canvas');
    // A software canvas, as the worker's (workerPictures.ts): the same pixels whichever drew them
    // (an accelerated canvas antialiases the borders otherwise, so a project reopened on the page
    // did not look exactly as saved once the worker's pictures were kept through picks).
    canvas.getContext('2d', { willReadFrequently: true });
    drawExactCells(canvas, surface, { ...paint, ...PICTURE_LAYOUT.texture(surface), valid: stack.valid, scutoid: stack.scutoid });
    texture = new THREE.CanvasTexture(canvas);
  }
  texture.flipY = false;
  if (picture instanceof ImageData || picture instanceof Uint8ClampedArray) {
    // A drag's draft or a picture of very many cells (the label image, one texel per pixel):
    // sampled as texels, no mipmaps or anisotropy, which cost a software GPU most of a frame
    // per streamed result.
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
