// A fixed part of a world (its box) on a canvas, y up: discs written into the pixels by
// DiscRaster (the cost is the pixels covered, whatever the number of balls), then walls and
// marks stroked over them with the 2D context. Drawing only: the "Galton board", "Pinball" and
// "Compression" pages hand it what carom answers.
import {DiscRaster, packColour} from './disc_raster.js';

export class WorldCanvas {
  // view: {x, y, width, height} in world units, y up.
  constructor(canvas, view) {
    this.canvas = canvas;
    this.context = canvas.getContext('2d', {alpha: false});
    this.raster = new DiscRaster(this.context);
    this.scale = 1;
    this.setView(view);
  }

  // Another part of the world (a page's new world): view as for the constructor.
  setView(view) {
    this.view = view;
    // The page's CSS sizes the canvas from this ratio (height auto, width capped by the screen).
    this.canvas.style.setProperty('--aspect', String(view.width / view.height));
  }

  // Pixels at the device's resolution for the canvas's size on the page.
  resize() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(this.canvas.clientWidth * ratio));
    const height = Math.max(1, Math.round(width * this.view.height / this.view.width));
    if (this.canvas.width !== width || this.canvas.height !== height) {
      this.canvas.width = width;
      this.canvas.height = height;
    }
    this.scale = width / this.view.width;
  }

  px(x) { return (x - this.view.x) * this.scale; }
  py(y) { return (this.view.y + this.view.height - y) * this.scale; }

  // Starts a frame: the canvas resized and filled with background ('#rrggbb').
  begin(background) {
    this.resize();
    this.raster.begin(packColour(background));
  }

  // A disc in world units, in a colour packed by packColour.
  disc(x, y, r, colour) { this.raster.disc(this.px(x), this.py(y), r * this.scale, colour); }

  // The discs go to the canvas; what follows is drawn over them.
  endDiscs() { this.raster.end(); }

  // Segments ({a, b}) stroked widthPx device-independent pixels wide.
  segments(list, colour, widthPx = 2) {
    const c = this.context;
    c.lineWidth = widthPx * (window.devicePixelRatio || 1);
    c.lineCap = 'round';
    c.strokeStyle = colour;
    c.beginPath();
    for (const s of list) {
      c.moveTo(this.px(s.a.x), this.py(s.a.y));
      c.lineTo(this.px(s.b.x), this.py(s.b.y));
    }
    c.stroke();
  }

  // Arcs ({center, radius, start_angle, end_angle}, counter-clockwise in the world) stroked.
  arcs(list, colour, widthPx = 2) {
    const c = this.context;
    c.lineWidth = widthPx * (window.devicePixelRatio || 1);
    c.strokeStyle = colour;
    for (const a of list) {
      c.beginPath();
      // y up: the world's angle θ is the screen's −θ, so the arc runs from −end to −start.
      c.arc(this.px(a.center.x), this.py(a.center.y), a.radius * this.scale, -a.end_angle,
            -a.start_angle);
      c.stroke();
    }
  }

  // A closed polygon ([{x, y}]) filled.
  polygon(points, colour) {
    const c = this.context;
    c.fillStyle = colour;
    c.beginPath();
    points.forEach((p, i) => (i ? c.lineTo : c.moveTo).call(c, this.px(p.x), this.py(p.y)));
    c.closePath();
    c.fill();
  }

  // Text at a world point, centred, size in CSS pixels.
  label(text, p, colour, sizePx = 12) {
    const c = this.context;
    c.fillStyle = colour;
    c.font = `${sizePx * (window.devicePixelRatio || 1)}px system-ui, sans-serif`;
    c.textAlign = 'center';
    c.textBaseline = 'middle';
    c.fillText(text, this.px(p.x), this.py(p.y));
  }

  frame() {
    const c = this.context;
    c.strokeStyle = '#333';
    c.lineWidth = 2;
    c.strokeRect(1, 1, this.canvas.width - 2, this.canvas.height - 2);
  }
}
