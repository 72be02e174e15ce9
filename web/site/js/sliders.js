// Range inputs with their value shown beside them.
export function slider(id, onInput) {
  const input = document.getElementById(id);
  const output = document.querySelector(`output[for="${id}"]`);
  const show = () => { if (output) output.textContent = input.value; };
  input.addEventListener('input', () => {
    show();
    onInput(Number(input.value));
  });
  show();
  return {get value() { return Number(input.value); }, input};
}

// Fills the elements marked data-readout="key" with texts[key]; keys left out show a dash.
export function fillReadout(texts) {
  for (const cell of document.querySelectorAll('[data-readout]')) {
    cell.textContent = texts[cell.dataset.readout] ?? '—';
  }
}
