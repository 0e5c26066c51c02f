// The element example's captions (examples/element.html): each shows its element's result or error.
for (const id of ['bare', 'wide']) {
  const element = document.getElementById(id);
  const out = document.getElementById(`${id}-out`);
  element.addEventListener('result', (event) => {
    // The headline: the mean over the element's realizations (default 5) with its 95 % CI and n.
    const h = event.detail.headline;
    const ci = h && h.ci95 ? `, 95 % CI ${h.ci95[0].toFixed(1)}–${h.ci95[1].toFixed(1)}` : '';
    out.textContent = h && h.percentScutoids !== null
      ? `${h.percentScutoids.toFixed(1)} % scutoids (${h.realizations > 1 ? `mean of n = ${h.realizations}${ci}` : 'one realization'})`
      : `${event.detail.percentScutoids.toFixed(1)} % scutoids`;
    element.dataset.done = 'true';
  });
  element.addEventListener('error', (event) => {
    out.textContent = event.detail.message;
    element.dataset.done = 'error';
  });
}
