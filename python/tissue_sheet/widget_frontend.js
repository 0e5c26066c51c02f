// The anywidget front end of tissue_sheet.Sheet, appended to the standalone element's module by
// scripts/bundle-python-widget.mjs (so `<tissue-sheet>` is registered above, once per page: the
// element's module guards customElements.define, which makes a re-run cell harmless).
//
// Traits: `config` both ways (Python sets it: the element re-runs; a run in the widget writes the
// configuration that ran back, so Python sees a change made in the widget), `result`, `error`,
// `compute_site` and `realizations`. Custom messages: sweeps and figures (see widget.py).
const __tissueSheetWidget = (() => {
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  // One view per model answers the kernel's requests (a widget shown twice runs a sweep once).
  const answering = new WeakMap();

  function render({ model, el }) {
    const sheet = document.createElement('tissue-sheet');
    sheet.style.display = 'block';
    const applyLook = () => {
      const realizations = model.get('realizations');
      if (realizations) sheet.setAttribute('realizations', String(realizations));
      else sheet.removeAttribute('realizations');
      sheet.style.height = model.get('height');
    };
    applyLook();
    model.on('change:realizations', applyLook);
    model.on('change:height', applyLook);
    const progress = document.createElement('div');
    progress.className = 'tissue-sheet-widget-progress';
    progress.hidden = true;
    const bar = document.createElement('progress');
    const label = document.createElement('span');
    label.style.marginLeft = '0.5em';
    progress.append(bar, label);
    el.append(sheet, progress);

    // The configuration the element last ran (what was written back to Python): setting it
    // again from Python is not a change.
    let ran = null;
    const applyConfig = () => {
      const config = model.get('config');
      if (ran !== null && same(config, ran)) return;
      sheet.config = config ?? {};
    };
    const onConfig = () => applyConfig();
    model.on('change:config', onConfig);
    applyConfig();

    const onResult = () => {
      const result = sheet.exportResult();
      ran = result.config;
      model.set('result', result);
      model.set('error', '');
      model.set('compute_site', sheet.computeSite ?? {});
      if (!same(model.get('config'), result.config)) model.set('config', result.config);
      model.save_changes();
    };
    const onError = (event) => {
      model.set('error', event.detail?.message ?? String(event.detail));
      model.save_changes();
    };
    sheet.addEventListener('result', onResult);
    sheet.addEventListener('error', onError);

    const showProgress = (finished, total, text) => {
      progress.hidden = false;
      bar.max = Math.max(total, 1);
      bar.value = finished;
      label.textContent = text;
    };
    const onMessage = async (msg) => {
      if (answering.get(model) !== sheet) return;
      if (msg?.type === 'sweep') {
        const { id, spec } = msg;
        const onProgress = (event) => {
          const d = event.detail;
          showProgress(d.finished, d.total, `sweep: ${d.finished} of ${d.total} runs${d.error ? ` (a run failed: ${d.error})` : ''}`);
          model.send({ type: 'sweep-progress', id, finished: d.finished, total: d.total, skipped: d.skipped, error: d.error ?? null });
        };
        sheet.addEventListener('sweep-progress', onProgress);
        try {
          showProgress(0, 1, 'sweep: starting');
          // A view answers: a cell waiting in Python (sheet.sweep(spec)) knows the sheet is shown.
          model.send({ type: 'sweep-started', id });
          const out = await sheet.sweep(spec);
          showProgress(out.completed + out.skipped, out.completed + out.skipped, `sweep: ${out.completed} runs done${out.aborted ? ' (aborted)' : ''}`);
          model.send({ type: 'sweep-done', id, runsCsv: out.runsCsv, aggregateCsv: out.aggregateCsv, completed: out.completed, aborted: out.aborted });
        } catch (e) {
          showProgress(0, 1, `sweep failed: ${e?.message ?? e}`);
          model.send({ type: 'sweep-error', id, message: String(e?.message ?? e), name: e?.name ?? 'Error' });
        } finally {
          sheet.removeEventListener('sweep-progress', onProgress);
        }
      } else if (msg?.type === 'figure') {
        const { id } = msg;
        try {
          const blob = await sheet.toBlob({ type: msg.mime ?? 'image/png' });
          model.send({ type: 'figure-done', id, mime: blob.type }, undefined, [await blob.arrayBuffer()]);
        } catch (e) {
          model.send({ type: 'figure-error', id, message: String(e?.message ?? e) });
        }
      }
    };
    if (!answering.has(model) || !answering.get(model).isConnected) answering.set(model, sheet);
    model.on('msg:custom', onMessage);

    return () => {
      model.off('change:config', onConfig);
      model.off('change:realizations', applyLook);
      model.off('change:height', applyLook);
      model.off('msg:custom', onMessage);
      sheet.removeEventListener('result', onResult);
      sheet.removeEventListener('error', onError);
      if (answering.get(model) === sheet) answering.delete(model);
    };
  }

  return { render };
})();
export default __tissueSheetWidget;
