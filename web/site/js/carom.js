// Loads carom's WebAssembly module once; every page imports `carom` from here. Everything the
// pages compute goes through it: the pages themselves hold no physics.
import createCarom from '../carom_web.js';

export const carom = await createCarom();

// Runs fn; if the library refuses an argument (a JavaScript Error carrying
// carom::InvalidArgument's message), shows the message in the page's error line and returns
// undefined instead of throwing.
export function attempt(fn) {
  const line = document.getElementById('error-line');
  try {
    const result = fn();
    if (line) line.textContent = '';
    return result;
  } catch (error) {
    if (!line) throw error;
    line.textContent = String(error.message ?? error);
    return undefined;
  }
}
