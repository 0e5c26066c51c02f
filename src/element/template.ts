/** The element's Shadow DOM: the 3D view, a caption with % scutoids, and a status line. */
export const TEMPLATE = `
<style>
  :host { display: block; position: relative; width: 480px; height: 320px; font: 13px system-ui, sans-serif; color: #1d232a; contain: content; }
  :host([hidden]) { display: none; }
  .frame { position: absolute; inset: 0; border: 1px solid #d9dde3; border-radius: 6px; overflow: hidden; background: #f4f4f0; }
  canvas { width: 100%; height: 100%; display: block; }
  .caption { position: absolute; left: 8px; top: 6px; background: #ffffffd0; padding: 2px 6px; border-radius: 4px; }
  .percent { font-weight: 700; color: #8a1c12; }
  .status { position: absolute; left: 8px; bottom: 6px; right: 8px; font-size: 12px; color: #5b6673; }
  .status.error { color: #8a1c12; font-weight: 600; background: #fdecea; padding: 2px 6px; border-radius: 4px; }
</style>
<div class="frame" part="frame">
  <canvas part="view" aria-label="3D view of the sheet: drag to orbit, scroll to zoom"></canvas>
  <div class="caption" part="caption"><span class="percent" part="percent">–</span> scutoids</div>
  <div class="status" part="status" role="status"></div>
</div>
`;
