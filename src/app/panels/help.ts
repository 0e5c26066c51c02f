/**
 * The help layer: a dialog with the glossary (scutoid, surface ratio, Voronoi k, label vs exact
 * adjacency, valid cells, Lewis, Aboav-Weaire), the references, the version and how to cite
 * tissue-sheet. Opened by the header's button, or by "?" anywhere outside a text field; closed
 * by Escape (the dialog's own behaviour) or its Close button.
 */
export function bindHelp(button: HTMLElement, dialog: HTMLDialogElement): void {
  const open = () => {
    if (!dialog.open) dialog.showModal();
  };
  button.addEventListener('click', open);
  document.addEventListener('keydown', (event) => {
    const target = event.target as HTMLElement | null;
    const typing = target?.closest('input, select, textarea, [contenteditable]');
    if (event.key === '?' && !typing && !event.ctrlKey && !event.metaKey && !event.altKey) open();
  });
}
