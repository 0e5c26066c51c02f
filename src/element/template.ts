/** The element's Shadow DOM: the 3D view, a caption with % scutoids and its method, a source question, and a status line. */
export const TEMPLATE = `
<style>
  :host { display: block; position: relative; width: 480px; height: 320px; font: 13px system-ui, sans-serif; color: #1d232a; contain: content; }
  :host([hidden]) { display: none; }
  .frame { position: absolute; inset: 0 0 3.4em 0; border: 1px solid #d9dde3; border-radius: 6px; overflow: hidden; background: #f4f4f0; }
  canvas { width: 100%; height: 100%; display: block; }
  .caption { position: absolute; left: 8px; top: 6px; background: #ffffffd0; padding: 2px 6px; border-radius: 4px; }
  .percent { font-weight: 700; color: #8a1c12; }
  /* Under the view, never over it (issue 26): three lines, then it scrolls. */
  .status { position: absolute; left: 2px; bottom: 0; right: 2px; height: 3.2em; overflow: auto; font-size: 12px; line-height: 1.05em; color: #5b6673; }
  .status.error { color: #8a1c12; font-weight: 600; background: #fdecea; padding: 2px 6px; border-radius: 4px; }
  .method { color: #5b6673; font-size: 11px; }
  .ask { position: absolute; left: 8px; right: 8px; top: 34px; background: #fff8e1; border: 1px solid #e0c36a; border-radius: 4px; padding: 6px 8px; }
  .ask[hidden] { display: none; }
  .ask p { margin: 0 0 4px; }
</style>
<div class="frame" part="frame">
  <canvas part="view" aria-label="3D view of the sheet: drag to orbit, scroll to zoom"></canvas>
  <div class="caption" part="caption"><span class="percent" part="percent">–</span> scutoids <span class="method" part="method"></span></div>
  <div class="ask" part="ask" role="region" aria-label="a source asks to be loaded" hidden><p></p><button type="button"></button></div>
</div>
<div class="status" part="status" role="status"></div>
`;
