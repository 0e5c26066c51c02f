/**
 * Binds the measure card to the project file (section `measured`, measureProject.ts): saving
 * keeps the shown tissue's files, option fields, result and comparison; opening restores the
 * fields and measures the kept files again (the saved comparison shown as saved), then checks
 * that the re-measurement gives the saved numbers and says so.
 */
import { fromBase64, toBase64 } from '../model/base64';
import { MAX_KEPT_BYTES, readMeasuredSection, sameMeasurement, type MeasuredSection } from '../model/measureProject';
import { registerProjectSection } from '../model/projectSections';
import type { MeasurePanel } from './measurePanel';

export function registerMeasuredSection(panel: MeasurePanel, root: HTMLElement): void {
  let prepared: { files: File[]; encoded: MeasuredSection['files']; omitted?: string } | null = null;
  registerProjectSection('measured', {
    async prepare() {
      const shown = panel.shownTissue();
      if (!shown) return;
      if (prepared?.files.length === shown.files.length && prepared.files.every((f, k) => f === shown.files[k])) return;
      const total = shown.files.reduce((a, f) => a + f.size, 0);
      if (total > MAX_KEPT_BYTES) {
        prepared = {
          files: shown.files,
          encoded: null,
          omitted: `the measured files (${(total / 2 ** 20).toFixed(1)} MiB) are over the ${MAX_KEPT_BYTES / 2 ** 20} MiB a project keeps`,
        };
        return;
      }
      const encoded = [];
      for (const file of shown.files) encoded.push({ name: file.name, type: file.type, base64: toBase64(new Uint8Array(await file.arrayBuffer())) });
      prepared = { files: shown.files, encoded };
    },
    save() {
      const shown = panel.shownTissue();
      if (!shown) return null;
      const fields: Record<string, string | boolean> = {};
      for (const field of panel.fields()) fields[field.id] = field.type === 'checkbox' ? field.checked : field.value;
      const same = prepared && prepared.files.every((f, k) => f === shown.files[k]);
      const section: MeasuredSection = {
        mode: shown.mode,
        files: same ? prepared!.encoded : null,
        ...(same && prepared!.omitted ? { omitted: prepared!.omitted } : !same ? { omitted: 'the files were not read before saving' } : {}),
        fields,
        result: shown.result,
        comparison: shown.comparison,
        note: shown.note,
      };
      return section;
    },
    async open(data, file) {
      const section = readMeasuredSection(data, file);
      const known = new Map(panel.fields().map((f) => [f.id, f]));
      for (const [id, value] of Object.entries(section.fields)) {
        const field = known.get(id);
        if (!field) continue; // a field of another version of the page: its default stays
        if (field.type === 'checkbox') field.checked = value === true;
        else field.value = String(value);
      }
      if (!section.files)
        throw new Error(`${file}: the measured tissue was saved without its files (${section.omitted ?? 'not kept'}); drop them again to draw it.`);
      const files = section.files.map(
        (f, k) => new File([fromBase64(f.base64, `${file}: sections.measured.files[${k}]`) as BlobPart], f.name, { type: f.type }),
      );
      await panel.measure(files, { comparison: section.comparison, note: section.note });
      const shown = panel.shownTissue();
      const status = root.querySelector<HTMLElement>('#measure-status')!;
      if (!shown) return;
      status.dataset.reopened = sameMeasurement(shown.result, section.result) ? 'same' : 'different';
      status.textContent =
        status.dataset.reopened === 'same'
          ? `Opened the measured tissue of ${file}: its files measured again give the saved numbers; the model comparison is shown as saved (not re-run).`
          : `Opened the measured tissue of ${file}: measured again, its numbers differ from the saved ones (another version of tissue-sheet?); the screen shows the new measurement, the model comparison as saved.`;
    },
  });
}
