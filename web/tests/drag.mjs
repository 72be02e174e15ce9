// Dragging on an SVG figure in world units, with the mouse or with a real touch.

// Where world point p of the page's SVG figure is on the screen: through the figure's world
// group, which flips y so that it points up.
export async function figurePoint(page, p) {
  return page.evaluate(({x, y}) => {
    const svg = document.getElementById('figure');
    const point = svg.createSVGPoint();
    point.x = x;
    point.y = y;
    const on = point.matrixTransform(svg.querySelector('g.world').getScreenCTM());
    return {x: on.x, y: on.y};
  }, p);
}

export async function mouseDrag(page, start, end) {
  await page.mouse.move(start.x, start.y);
  await page.mouse.down();
  await page.mouse.move(end.x, end.y, {steps: 12});
  await page.mouse.up();
}

// Chromium turns these touch events into pointer events, as on a phone.
export async function touchDrag(page, start, end) {
  const cdp = await page.context().newCDPSession(page);
  const touch = (type, p) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: type === 'touchEnd' ? [] : [{x: p.x, y: p.y}]});
  await touch('touchStart', start);
  const steps = 12;
  for (let i = 1; i <= steps; ++i) {
    await touch('touchMove', {x: start.x + (end.x - start.x) * i / steps,
                              y: start.y + (end.y - start.y) * i / steps});
  }
  await touch('touchEnd');
  await cdp.detach();
}

// True when `value` printed with as many significant digits as `shown` has equals `shown`
// (the pages print numbers like C's %g).
export function sameDigits(shown, value) {
  const digits = shown.replace(/e.*$/, '').replace(/^-?0*\.?0*/, '').replace('.', '').length;
  return Number(Number(value).toPrecision(Math.max(1, digits))) === Number(shown);
}
