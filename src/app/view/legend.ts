/** The legend of side colours, and of the scutoid and border-cell marks. */
import { SIDE_COLORS, SIDE_LABELS } from '../../view/sideColors';

export function renderLegend(container: HTMLElement): void {
  container.replaceChildren();
  const list = document.createElement('ul');
  list.className = 'legend';
  SIDE_LABELS.forEach((label, k) => list.append(item(`${label} sides`, `background:${SIDE_COLORS[k]}`)));
  list.append(item('scutoid (striped)', `background:repeating-linear-gradient(45deg,#141414 0 3px,#f0e442 3px 9px)`));
  list.append(item('border cell (not counted)', 'background:#e6e6e6'));
  list.append(item('picked cell', 'background:#ffffff;border:1px solid #333'));
  container.append(list);
}

function item(text: string, swatchStyle: string): HTMLLIElement {
  const li = document.createElement('li');
  const swatch = document.createElement('span');
  swatch.className = 'swatch';
  swatch.setAttribute('style', swatchStyle);
  li.append(swatch, document.createTextNode(text));
  return li;
}
