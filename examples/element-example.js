// The element example's captions (examples/element.html): each shows its element's result or error.
for (const id of ['bare', 'wide']) {
  const element = document.getElementById(id);
  const out = document.getElementById(`${id}-out`);
  element.addEventListener('result', (event) => {
    out.textContent = `${event.detail.percentScutoids.toFixed(1)} % scutoids`;
    element.dataset.done = 'true';
  });
  element.addEventListener('error', (event) => {
    out.textContent = event.detail.message;
    element.dataset.done = 'error';
  });
}
