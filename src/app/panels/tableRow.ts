/** One row of the results panel's tables: the first cell a row header; text, never HTML. */
export function tableRow(cells: readonly (string | number)[], header = false, key?: string, value?: number): HTMLTableRowElement {
  const tr = document.createElement('tr');
  cells.forEach((text, k) => {
    const cell = document.createElement(header || k === 0 ? 'th' : 'td');
    cell.textContent = String(text);
    if (!header && k === 0) cell.setAttribute('scope', 'row');
    tr.append(cell);
  });
  if (key) tr.dataset.key = key;
  if (value !== undefined) tr.dataset.value = String(value);
  return tr;
}
