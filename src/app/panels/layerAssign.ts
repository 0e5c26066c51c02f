/**
 * Which file is which layer, shown and reassignable (issue 26): one row per file with a picker
 * of its layer ("1: basal" ... "n: apical"). A file dialog hands files over in alphabetical
 * order (apical.png before basal.png), so the order given is only a first guess: choosing a
 * layer for a file swaps it with the file that had that layer, and the tissue is measured again
 * in the new order. The list says which file is taken as basal.
 */

/** The layer name of position `k` of `n` (0 basal, n - 1 apical). */
function layerName(k: number, n: number): string {
  return k === 0 ? 'basal' : k === n - 1 ? 'apical' : `layer ${k + 1}`;
}

/** `order` with the file at position `from` moved to position `to` by swapping with the file there. */
export function reassign<T>(order: readonly T[], from: number, to: number): T[] {
  const out = [...order];
  [out[from], out[to]] = [out[to], out[from]];
  return out;
}

export class LayerAssign {
  constructor(
    private readonly root: HTMLElement,
    private readonly onReorder: (files: File[]) => void,
  ) {}

  /** Shows `files` in layer order (basal first); hidden for fewer than two files. */
  show(files: readonly File[]): void {
    this.root.replaceChildren();
    this.root.hidden = files.length < 2;
    if (files.length < 2) return;
    const n = files.length;
    const title = document.createElement('p');
    title.className = 'small';
    title.textContent = `Layers, basal first: ${files[0].name} is taken as basal, ${files[n - 1].name} as apical. Pick another layer for a file to reassign it (it swaps with the file that had that layer; the tissue is measured again).`;
    const list = document.createElement('ol');
    list.className = 'layer-files';
    files.forEach((file, k) => {
      const item = document.createElement('li');
      const label = document.createElement('label');
      const select = document.createElement('select');
      select.dataset.file = file.name;
      select.setAttribute('aria-label', `layer of ${file.name}`);
      for (let j = 0; j < n; j++) select.append(new Option(`${j + 1}: ${layerName(j, n)}`, String(j), false, j === k));
      select.addEventListener('change', () => this.onReorder(reassign(files, k, Number(select.value))));
      label.append(`${file.name} `, select);
      item.append(label);
      list.append(item);
    });
    this.root.append(title, list);
  }
}
