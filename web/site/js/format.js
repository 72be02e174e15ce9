// Numbers as the pages print them: `digits` significant digits, trailing zeros dropped, like C's
// %g (which `carom sweep` uses), and -0 shown as 0.
export function num(value, digits = 6) {
  if (!Number.isFinite(value)) return String(value);
  if (value === 0) return '0';
  const exponent = Math.floor(Math.log10(Math.abs(value)));
  if (exponent < -4 || exponent >= digits) {
    const [mantissa, power] = value.toExponential(digits - 1).split('e');
    return `${trimZeros(mantissa)}e${power}`;
  }
  return trimZeros(value.toPrecision(digits));
}

function trimZeros(text) {
  return text.includes('.') ? text.replace(/\.?0+$/, '') : text;
}

export function vec(v, digits = 6) {
  return `(${num(v.x, digits)}, ${num(v.y, digits)})`;
}
