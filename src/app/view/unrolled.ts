/**
 * The unrolled diagrams: one 2D canvas per surface of the stack, side by side, drawn from the
 * label images (cells coloured by sides, scutoids striped, border cells faded). Widths keep the
 * surfaces' true proportions, so a tube's outer surface is drawn wider than its inner one.
 */
import type { ViewStack } from '../model/stack';
import { flipRows, paintSurface } from './sideColors';

export function drawUnrolled(container: HTMLElement, stack: ViewStack, highlightScutoids: boolean): void {
  container.replaceChildren();
  for (const surface of stack.surfaces) {
    const { width, height } = surface.image.grid;
    const figure = document.createElement('figure');
    figure.className = 'unrolled';
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    canvas.dataset.surface = surface.name;
    canvas.setAttribute('role', 'img');
    canvas.setAttribute('aria-label', `unrolled ${surface.name} surface, ${width} x ${height} texels`);
    const context = canvas.getContext('2d');
    if (context) {
      const rgba = paintSurface(surface, { highlightScutoids, valid: stack.valid, scutoid: stack.scutoid });
      context.putImageData(new ImageData(flipRows(rgba, width, height), width, height), 0, 0);
    }
    const caption = document.createElement('figcaption');
    const ratio = surface.ratio !== 1 ? `, ratio ${surface.ratio.toFixed(2)}` : '';
    const offset = surface.offset !== 0 ? `, ${surface.offset.toFixed(1)} µm` : '';
    caption.textContent = `${surface.name}${surface.role === 'seeded' ? ' (seeded)' : ''}${offset}${ratio}`;
    figure.append(canvas, caption);
    container.append(figure);
  }
}
