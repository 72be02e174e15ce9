// An SVG figure in world units with draggable handles. y points up, as in carom's scene files and
// the pictures `carom render` and `carom sweep --svg` draw: the shapes live in a group flipped by
// scale(1, -1), and text is set outside it so that it reads the right way up. Drawing helpers
// take plain {x, y} points from the library and only place shapes: no physics here.
const SVG_NS = 'http://www.w3.org/2000/svg';

// Dragged points snap to this grid, so that what the page shows (and a test types into
// `carom sweep`) is exactly the point the library was given.
const SNAP = 10;  // per length unit: 0.1
export const snap = (value) => Math.round(value * SNAP) / SNAP;

// Sizes on the screen, in CSS pixels, whatever the view's scale: the smallest handle (a
// fingertip covers about 30), label text, the gap between a label and what it names, and an
// arrow head's length.
const MIN_HANDLE_RADIUS_PX = 15;
const LABEL_FONT_PX = 15;
const LABEL_GAP_PX = 3;
const ARROW_HEAD_PX = 12;

// When the view refits: room around the drawing, as a share of its longer side; and how small
// the drawing may get in the view (a share of both sides) before the view closes in on it.
const VIEW_MARGIN = 0.08;
const SMALLEST_SHARE = 0.4;
// Grid lines at 1, 10, 100 ... length units: the finest step that gives at most this many.
const MOST_GRID_LINES = 60;

function element(name, attributes, parent) {
  const node = document.createElementNS(SVG_NS, name);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (parent) parent.appendChild(node);
  return node;
}

// An axis-aligned box in world units, empty until something is added.
class Extent {
  constructor() {
    this.x0 = Infinity;
    this.y0 = Infinity;
    this.x1 = -Infinity;
    this.y1 = -Infinity;
  }

  add(p, reach = 0) {
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) return;
    this.x0 = Math.min(this.x0, p.x - reach);
    this.y0 = Math.min(this.y0, p.y - reach);
    this.x1 = Math.max(this.x1, p.x + reach);
    this.y1 = Math.max(this.y1, p.y + reach);
  }

  get empty() { return !(this.x0 <= this.x1); }
}

const boxesMeet = (a, b) => a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;

function boxMeetsCircle(box, c) {
  const dx = Math.max(box.x0 - c.x, 0, c.x - box.x1);
  const dy = Math.max(box.y0 - c.y, 0, c.y - box.y1);
  return dx * dx + dy * dy < c.r * c.r;
}

export class Figure {
  // view: the world rectangle shown at first {x, y, width, height} (x, y its lower-left corner);
  // the view never gets smaller than this, and keeps its proportions.
  constructor(svg, view) {
    this.svg = svg;
    this.least = view;
    svg.setAttribute('preserveAspectRatio', 'xMidYMid meet');
    this.world = element('g', {class: 'world', transform: 'scale(1 -1)'}, svg);
    this.grid = element('g', {class: 'grid'}, this.world);
    this.layer = element('g', {}, this.world);
    this.handleLayer = element('g', {class: 'handles'}, this.world);
    this.labels = element('g', {class: 'labels'}, svg);
    this.handles = [];
    this.dragging = false;
    this.extent = new Extent();
    this.labelBoxes = [];
    this.show(view);
  }

  // Shows the world rectangle view: the SVG's viewBox (y flipped) and a grid over it.
  show(view) {
    this.view = view;
    this.svg.setAttribute('viewBox', `${view.x} ${-(view.y + view.height)} ${view.width} ` +
                                     `${view.height}`);
    this.grid.replaceChildren();
    let step = 1;
    while (Math.max(view.width, view.height) / step > MOST_GRID_LINES) step *= 10;
    const lines = (from, to, draw) => {
      for (let v = Math.ceil(from / step) * step; v <= to; v += step) draw(v);
    };
    const axis = (v) => (v === 0 ? 'axis' : '');
    lines(view.x, view.x + view.width, (x) => element('line', {
      x1: x, y1: view.y, x2: x, y2: view.y + view.height, class: axis(x)}, this.grid));
    lines(view.y, view.y + view.height, (y) => element('line', {
      x1: view.x, y1: y, x2: view.x + view.width, y2: y, class: axis(y)}, this.grid));
    this.svg.dataset.view = [view.x, view.y, view.width, view.height].join(' ');
  }

  // CSS pixels per length unit as the figure is laid out now.
  pixelsPerUnit() { return this.svg.getScreenCTM()?.a || 1; }

  // Places the handles, clears the figure and calls draw(); when the drawing left the view (or
  // shrank well inside it) the view refits around it and everything is placed and drawn again
  // at the new scale. Not while a handle is dragged: the view stays put under the pointer.
  update(draw) {
    for (let pass = 0; pass < 2; ++pass) {
      for (const h of this.handles) h.place();
      this.clear();
      draw();
      if (this.dragging || !this.refit()) return;
    }
  }

  clear() {
    this.layer.replaceChildren();
    this.labels.replaceChildren();
    this.extent = new Extent();
    this.labelBoxes = [];
  }

  // Shows a new view when the drawing (with a margin) does not fit in this one, or fills less
  // than SMALLEST_SHARE of it both ways. Returns whether the view changed.
  refit() {
    const e = this.extent;
    if (e.empty) return false;
    const margin = VIEW_MARGIN * Math.max(e.x1 - e.x0, e.y1 - e.y0, 1);
    const want = {x0: e.x0 - margin, y0: e.y0 - margin, x1: e.x1 + margin, y1: e.y1 + margin};
    const v = this.view;
    const fits = want.x0 >= v.x && want.y0 >= v.y && want.x1 <= v.x + v.width &&
                 want.y1 <= v.y + v.height;
    const larger = v.width > this.least.width || v.height > this.least.height;
    const small = want.x1 - want.x0 < SMALLEST_SHARE * v.width &&
                  want.y1 - want.y0 < SMALLEST_SHARE * v.height;
    if (fits && !(larger && small)) return false;
    // The wanted box grown to the figure's proportions and to at least the first view's size,
    // around the same middle.
    const aspect = this.least.width / this.least.height;
    let width = Math.max(want.x1 - want.x0, this.least.width);
    let height = Math.max(want.y1 - want.y0, this.least.height);
    if (width / height > aspect) height = width / aspect; else width = height * aspect;
    const middle = {x: (want.x0 + want.x1) / 2, y: (want.y0 + want.y1) / 2};
    this.show({x: middle.x - width / 2, y: middle.y - height / 2, width, height});
    return true;
  }

  circle(center, radius, cls) {
    this.extent.add(center, radius);
    return element('circle', {cx: center.x, cy: center.y, r: radius, class: cls}, this.layer);
  }

  line(from, to, cls) {
    this.extent.add(from);
    this.extent.add(to);
    return element('line', {x1: from.x, y1: from.y, x2: to.x, y2: to.y, class: cls}, this.layer);
  }

  // An arrow from `from` along `vector`, its head a fixed size on the screen; the label (if
  // any) goes where it covers no handle and no other label: beyond the tip, beside it, or
  // beside the middle of the arrow.
  arrow(from, vector, cls, label) {
    const length = Math.hypot(vector.x, vector.y);
    const group = element('g', {class: `arrow ${cls}`}, this.layer);
    if (length === 0) return group;
    const to = {x: from.x + vector.x, y: from.y + vector.y};
    this.extent.add(from);
    this.extent.add(to);
    element('line', {x1: from.x, y1: from.y, x2: to.x, y2: to.y}, group);
    const head = Math.min(ARROW_HEAD_PX / this.pixelsPerUnit(), length * 0.4);
    const u = {x: vector.x / length, y: vector.y / length};
    const back = {x: to.x - u.x * head, y: to.y - u.y * head};
    const side = {x: -u.y * head * 0.4, y: u.x * head * 0.4};
    element('polygon', {points: `${to.x},${to.y} ${back.x + side.x},${back.y + side.y} ` +
                                `${back.x - side.x},${back.y - side.y}`}, group);
    if (label) {
      const middle = {x: from.x + vector.x / 2, y: from.y + vector.y / 2};
      const left = {x: -u.y, y: u.x};
      const right = {x: u.y, y: -u.x};
      this.label([[to, u], [to, left], [to, right], [middle, left], [middle, right]], label,
                 `label ${cls}`);
    }
    return group;
  }

  // Text at the first of spots ([point, direction] in world units) where it covers no handle
  // and no earlier label, moved off the point in that direction; at the first spot when every
  // one is taken. Set upright, outside the flipped group, a fixed size on the screen.
  label(spots, content, cls) {
    const unit = 1 / this.pixelsPerUnit();
    const node = element('text', {class: cls, 'font-size': LABEL_FONT_PX * unit,
                                  'text-anchor': 'middle', 'dominant-baseline': 'central'},
                         this.labels);
    node.textContent = content;
    node.setAttribute('x', 0);
    node.setAttribute('y', 0);
    const size = node.getBBox();
    const obstacles = this.handles.filter((h) => !h.ball).map((h) => h.circle());
    const reach = Math.max(0, ...obstacles.map((c) => c.r)) + LABEL_GAP_PX * unit;
    let chosen = null;
    for (const [at, direction] of spots) {
      const d = Math.hypot(direction.x, direction.y) || 1;
      const u = {x: direction.x / d, y: direction.y / d};
      // Far enough along u that the text's box clears a handle's circle around the point.
      const along = reach + Math.abs(u.x) * size.width / 2 + Math.abs(u.y) * size.height / 2;
      const c = {x: at.x + u.x * along, y: at.y + u.y * along};
      const box = {x0: c.x - size.width / 2, x1: c.x + size.width / 2,
                   y0: c.y - size.height / 2, y1: c.y + size.height / 2};
      const free = !obstacles.some((o) => boxMeetsCircle(box, o)) &&
                   !this.labelBoxes.some((b) => boxesMeet(box, b));
      if (!chosen || free) chosen = {c, box};
      if (free) break;
    }
    node.setAttribute('x', chosen.c.x);
    node.setAttribute('y', -chosen.c.y);
    this.labelBoxes.push(chosen.box);
    this.extent.add({x: chosen.box.x0, y: chosen.box.y0});
    this.extent.add({x: chosen.box.x1, y: chosen.box.y1});
    return node;
  }

  // An arc of carom::Arc's shape: counter-clockwise in the library's angle. In the flipped group
  // y points up, so that is SVG's positive sweep direction there.
  arc(arc, cls) {
    const span = arc.end_angle - arc.start_angle;
    if (span >= 2 * Math.PI) return this.circle(arc.center, arc.radius, cls);
    const at = (angle) => ({x: arc.center.x + arc.radius * Math.cos(angle),
                            y: arc.center.y + arc.radius * Math.sin(angle)});
    const from = at(arc.start_angle);
    const to = at(arc.end_angle);
    const large = span > Math.PI ? 1 : 0;
    // The extent of the whole circle: a little generous for a short arc, never too small.
    this.extent.add(arc.center, arc.radius);
    return element('path', {d: `M ${from.x} ${from.y} A ${arc.radius} ${arc.radius} 0 ${large} 1 ` +
                                `${to.x} ${to.y}`, class: cls}, this.layer);
  }

  // A handle the user drags. get() gives its world position, set(p) receives the snapped new
  // one; radius() its size in world units; ball: a ball's own disc (labels may cover it). After
  // every move, and when the drag ends, onChange() redraws the figure.
  handle(name, {get, set, radius, cls, ball = false}, onChange) {
    const node = element('circle', {class: `handle ${cls ?? ''}`, 'data-handle': name},
                         this.handleLayer);
    let offset = null;
    node.addEventListener('pointerdown', (event) => {
      event.preventDefault();
      node.setPointerCapture(event.pointerId);
      const p = this.toWorld(event);
      const at = get();
      offset = {x: at.x - p.x, y: at.y - p.y};
      this.dragging = true;
      node.classList.add('dragging');
    });
    node.addEventListener('pointermove', (event) => {
      if (!offset) return;
      const p = this.toWorld(event);
      set({x: snap(p.x + offset.x), y: snap(p.y + offset.y)});
      onChange();
    });
    const end = () => {
      if (!offset) return;
      offset = null;
      this.dragging = false;
      node.classList.remove('dragging');
      onChange();  // now the view may refit around what the drag made
    };
    node.addEventListener('pointerup', end);
    node.addEventListener('pointercancel', end);
    const size = () => Math.max(radius(), MIN_HANDLE_RADIUS_PX / this.pixelsPerUnit());
    const handle = {
      ball,
      place() {
        const at = get();
        node.setAttribute('cx', at.x);
        node.setAttribute('cy', at.y);
        node.setAttribute('r', size());
      },
      circle() {
        const at = get();
        return {x: at.x, y: at.y, r: size()};
      },
    };
    this.handles.push(handle);
    return handle;
  }

  // The world point under a pointer event.
  toWorld(event) {
    const point = this.svg.createSVGPoint();
    point.x = event.clientX;
    point.y = event.clientY;
    return point.matrixTransform(this.world.getScreenCTM().inverse());
  }
}

// A legend in HTML beside the figure: sections [{title, entries: [{mark, cls, text}]}], each
// mark a small SVG drawn with the figure's own classes, so that its colours are the figure's.
// Marks: 'disc' and 'ring' (a ball), 'arrow', 'line', 'dot'.
export function fillLegend(container, sections) {
  container.replaceChildren();
  for (const {title, entries} of sections) {
    const section = document.createElement('section');
    const heading = document.createElement('h3');
    heading.textContent = title;
    const list = document.createElement('ul');
    section.append(heading, list);
    for (const {mark, cls, text} of entries) {
      const item = document.createElement('li');
      item.dataset.mark = `${mark} ${cls}`;
      const svg = element('svg', {viewBox: '0 -10 36 20', width: 36, height: 20,
                                  'aria-hidden': 'true'});
      if (mark === 'disc' || mark === 'ring') {
        element('circle', {cx: 18, cy: 0, r: 7, class: cls}, svg);
      } else if (mark === 'arrow') {
        const group = element('g', {class: `arrow ${cls}`}, svg);
        element('line', {x1: 2, y1: 0, x2: 26, y2: 0}, group);
        element('polygon', {points: '34,0 24,-4.5 24,4.5'}, group);
      } else if (mark === 'line') {
        element('line', {x1: 2, y1: 0, x2: 34, y2: 0, class: cls}, svg);
      } else if (mark === 'dot') {
        element('circle', {cx: 18, cy: 0, r: 3.5, class: cls}, svg);
      }
      const words = document.createElement('span');
      words.textContent = text;
      item.append(svg, words);
      list.append(item);
    }
    container.append(section);
  }
}
