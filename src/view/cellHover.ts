/**
 * Hover picking on the 3D view's canvas, shared by the app and the element: at most one pick per
 * animation frame (the newest pointer position), none while a button is held (the pointer is
 * orbiting or panning the camera), and `null` once when the pointer leaves or starts a drag.
 * The pick itself is SheetView3D.pickCell (accelerated on large closed meshes: see
 * SheetView3D.acceleratePicking).
 */
import type { PickedCell, SheetView3D } from './sheetView3d';

export interface HoverEvent {
  picked: PickedCell | null;
  clientX: number;
  clientY: number;
  /** False when the pointer moved within the same cell (only the position changed). */
  changed: boolean;
}

/** Calls `onHover` with the cell under the pointer when it changes; returns a function that stops it. */
export function trackCellHover(canvas: HTMLCanvasElement, view: SheetView3D, onHover: (event: HoverEvent) => void): () => void {
  let frame = 0;
  let pointer: { x: number; y: number } | null = null;
  let last: string | null = 'none';
  const emit = (picked: PickedCell | null, x: number, y: number, always = false) => {
    const key = picked ? `${picked.surface}:${picked.cell}` : null;
    const changed = key !== last;
    if (!always && !changed) return;
    last = key;
    onHover({ picked, clientX: x, clientY: y, changed });
  };
  const clear = () => {
    cancelAnimationFrame(frame);
    frame = 0;
    pointer = null;
    if (last !== null) emit(null, 0, 0);
  };
  const move = (event: PointerEvent) => {
    if (event.buttons !== 0) return clear();
    pointer = { x: event.clientX, y: event.clientY };
    if (frame) return;
    frame = requestAnimationFrame(() => {
      frame = 0;
      if (!pointer) return;
      const picked = view.pickCell(pointer.x, pointer.y);
      // The same cell: only the tooltip's place changes.
      emit(picked, pointer.x, pointer.y, picked !== null);
    });
  };
  canvas.addEventListener('pointermove', move);
  canvas.addEventListener('pointerleave', clear);
  canvas.addEventListener('pointerdown', clear);
  canvas.addEventListener('wheel', clear, { passive: true });
  return () => {
    clear();
    canvas.removeEventListener('pointermove', move);
    canvas.removeEventListener('pointerleave', clear);
    canvas.removeEventListener('pointerdown', clear);
    canvas.removeEventListener('wheel', clear);
  };
}
