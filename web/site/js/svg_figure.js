// An SVG figure in world units (y grows downwards, as on screen) with draggable handles. Drawing
// helpers take plain {x, y} points from the library and only place shapes: no physics here.
const SVG_NS = 'http://www.w3.org/2000/svg';

// Dragged points snap to this grid, so that what the page shows (and a test types into
// `carom sweep`) is exactly the point the library was given.
const SNAP = 10;  // per length unit: 0.1
export const snap = (value) => Math.round(value * SNAP) / SNAP;

// The smallest handle on the screen, in CSS pixels: a fingertip covers about 30.
const MIN_HANDLE_RADIUS_PX = 15;

function element(name, attributes, parent) {
  const node = document.createElementNS(SVG_NS, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (parent) parent.appendChild(node);
  return node;
}

export class Figure {
  // view: the visible world rectangle {x, y, width, height}.
  constructor(svg, view) {
    this.svg = svg;
    svg.setAttribute('viewBox', `${view.x} ${view.y} ${view.width} ${view.height}`);
    svg.setAttribute('preserveAspectRatio', 'xMidYMid meet');
    this.grid = element('g', {class: 'grid'}, svg);
    this.layer = element('g', {}, svg);
    this.handles = element('g', {class: 'handles'}, svg);
    for (let x = Math.ceil(view.x); x <= view.x + view.width; ++x) {
      element('line', {x1: x, y1: view.y, x2: x, y2: view.y + view.height,
                       class: x === 0 ? 'axis' : ''}, this.grid);
    }
    for (let y = Math.ceil(view.y); y <= view.y + view.height; ++y) {
      element('line', {x1: view.x, y1: y, x2: view.x + view.width, y2: y,
                       class: y === 0 ? 'axis' : ''}, this.grid);
    }
  }

  clear() { this.layer.replaceChildren(); }

  circle(center, radius, cls) {
    return element('circle', {cx: center.x, cy: center.y, r: radius, class: cls}, this.layer);
  }

  line(from, to, cls) {
    return element('line', {x1: from.x, y1: from.y, x2: to.x, y2: to.y, class: cls}, this.layer);
  }

  // An arrow from `from` along `vector`, with a head sized in world units.
  arrow(from, vector, cls, label) {
    const length = Math.hypot(vector.x, vector.y);
    const group = element('g', {class: `arrow ${cls}`}, this.layer);
    if (length === 0) return group;
    const to = {x: from.x + vector.x, y: from.y + vector.y};
    element('line', {x1: from.x, y1: from.y, x2: to.x, y2: to.y}, group);
    const head = Math.min(0.35, length * 0.4);
    const ux = vector.x / length;
    const uy = vector.y / length;
    const back = {x: to.x - ux * head, y: to.y - uy * head};
    const side = {x: -uy * head * 0.45, y: ux * head * 0.45};
    element('polygon', {points: `${to.x},${to.y} ${back.x + side.x},${back.y + side.y} ` +
                                `${back.x - side.x},${back.y - side.y}`}, group);
    if (label) this.text({x: to.x + ux * 0.3, y: to.y + uy * 0.3}, label, `label ${cls}`);
    return group;
  }

  text(at, content, cls) {
    const node = element('text', {x: at.x, y: at.y, class: cls}, this.layer);
    node.textContent = content;
    return node;
  }

  // An arc of carom::Arc's shape: counter-clockwise in the library's angle, which on a y-down
  // screen runs clockwise, SVG's positive sweep direction.
  arc(arc, cls) {
    const span = arc.end_angle - arc.start_angle;
    if (span >= 2 * Math.PI) return this.circle(arc.center, arc.radius, cls);
    const at = (angle) => ({x: arc.center.x + arc.radius * Math.cos(angle),
                            y: arc.center.y + arc.radius * Math.sin(angle)});
    const from = at(arc.start_angle);
    const to = at(arc.end_angle);
    const large = span > Math.PI ? 1 : 0;
    return element('path', {d: `M ${from.x} ${from.y} A ${arc.radius} ${arc.radius} 0 ${large} 1 ` +
                                `${to.x} ${to.y}`, class: cls}, this.layer);
  }

  // A handle the user drags. get() gives its world position, set(p) receives the snapped new
  // one; radius() its size in world units. After every move, onChange() redraws the figure.
  handle(name, {get, set, radius, cls}, onChange) {
    const node = element('circle', {class: `handle ${cls ?? ''}`, 'data-handle': name},
                         this.handles);
    let offset = null;
    node.addEventListener('pointerdown', (event) => {
      event.preventDefault();
      node.setPointerCapture(event.pointerId);
      const p = this.toWorld(event);
      const at = get();
      offset = {x: at.x - p.x, y: at.y - p.y};
      node.classList.add('dragging');
    });
    node.addEventListener('pointermove', (event) => {
      if (!offset) return;
      const p = this.toWorld(event);
      set({x: snap(p.x + offset.x), y: snap(p.y + offset.y)});
      onChange();
    });
    const end = () => {
      offset = null;
      node.classList.remove('dragging');
    };
    node.addEventListener('pointerup', end);
    node.addEventListener('pointercancel', end);
    const place = () => {
      const at = get();
      node.setAttribute('cx', at.x);
      node.setAttribute('cy', at.y);
      const pixelsPerUnit = this.svg.getScreenCTM()?.a || 1;
      node.setAttribute('r', Math.max(radius(), MIN_HANDLE_RADIUS_PX / pixelsPerUnit));
    };
    return {place};
  }

  toWorld(event) {
    const point = this.svg.createSVGPoint();
    point.x = event.clientX;
    point.y = event.clientY;
    return point.matrixTransform(this.svg.getScreenCTM().inverse());
  }
}
