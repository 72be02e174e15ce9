// Filled discs written straight into the canvas's pixels, with anti-aliased edges. With thousands
// of balls this is much cheaper than asking the 2D context for one arc each: the cost is the
// pixels covered (a fixed fraction of the box at a given packing fraction), not a path per ball.
// Drawing only.
export class DiscRaster {
  constructor(context) {
    this.context = context;
    this.image = null;
    this.pixels = null;
  }

  // Starts a frame of the canvas's current size, filled with colour (0xAABBGGRR).
  begin(colour) {
    const {width, height} = this.context.canvas;
    if (!this.image || this.image.width !== width || this.image.height !== height) {
      this.image = this.context.createImageData(width, height);
      this.pixels = new Uint32Array(this.image.data.buffer);
    }
    this.pixels.fill(colour);
  }

  // The disc (pixel units) in colour, its edge anti-aliased: a pixel whose centre lies d from
  // the disc's centre is covered r − d + ½ (clamped to [0, 1]) and mixed with what is under it
  // in that share. Pixels well inside are filled row by row; only the one or two at each end of
  // a row are mixed, so the cost stays that of the pixels covered.
  disc(x, y, r, colour) {
    const {width, height} = this.image;
    const pixels = this.pixels;
    const outer = r + 0.5;
    const inner = r - 0.5;
    const top = Math.max(0, Math.ceil(y - outer - 0.5));
    const bottom = Math.min(height - 1, Math.floor(y + outer - 0.5));
    for (let row = top; row <= bottom; ++row) {
      const dy = row + 0.5 - y;
      if (Math.abs(dy) >= outer) continue;
      const halfOuter = Math.sqrt(outer * outer - dy * dy);
      const left = Math.max(0, Math.ceil(x - halfOuter - 0.5));
      const right = Math.min(width - 1, Math.floor(x + halfOuter - 0.5));
      const start = row * width;
      // Columns [solidLeft, solidRight] lie wholly inside (d <= r − ½): one fill. None when
      // solidLeft is past right.
      let solidLeft = right + 1;
      let solidRight = right;
      if (inner > Math.abs(dy)) {
        const halfInner = Math.sqrt(inner * inner - dy * dy);
        const from = Math.max(left, Math.ceil(x - halfInner - 0.5));
        const to = Math.min(right, Math.floor(x + halfInner - 0.5));
        if (from <= to) {
          pixels.fill(colour, start + from, start + to + 1);
          solidLeft = from;
          solidRight = to;
        }
      }
      // The edge: the columns left of the solid span and those right of it (the loop jumps over
      // the span).
      const dy2 = dy * dy;
      for (let column = left; column <= right; ++column) {
        if (column === solidLeft) {
          column = solidRight;
          continue;
        }
        const dx = column + 0.5 - x;
        const cover = outer - Math.sqrt(dx * dx + dy2);
        if (cover <= 0) continue;
        const at = start + column;
        pixels[at] = cover >= 1 ? colour : mix(pixels[at], colour, cover);
      }
    }
  }

  end() { this.context.putImageData(this.image, 0, 0); }
}

// under and over (0xAABBGGRR, opaque) mixed: share of over, the rest of under.
function mix(under, over, share) {
  const keep = 1 - share;
  const r = ((under & 0xff) * keep + (over & 0xff) * share + 0.5) | 0;
  const g = (((under >>> 8) & 0xff) * keep + ((over >>> 8) & 0xff) * share + 0.5) | 0;
  const b = (((under >>> 16) & 0xff) * keep + ((over >>> 16) & 0xff) * share + 0.5) | 0;
  return (0xff000000 | (b << 16) | (g << 8) | r) >>> 0;
}

// '#rrggbb' as the 0xAABBGGRR number an Uint32Array over RGBA bytes holds on little-endian
// machines (every browser today).
export function packColour(hex) {
  const value = parseInt(hex.slice(1), 16);
  return (0xff000000 | ((value & 0xff) << 16) | (value & 0xff00) | (value >> 16)) >>> 0;
}

// Any CSS colour text ('red', '#f80', 'rgb(…)') as packColour's number, read back from a 1×1
// canvas; undefined for text that is not a colour.
export function packCssColour(text) {
  const probe = document.createElement('canvas').getContext('2d', {willReadFrequently: true});
  probe.fillStyle = '#010203';
  probe.fillStyle = text;
  if (probe.fillStyle === '#010203' && text.trim().toLowerCase() !== '#010203') return undefined;
  probe.fillRect(0, 0, 1, 1);
  const [r, g, b] = probe.getImageData(0, 0, 1, 1).data;
  return (0xff000000 | (b << 16) | (g << 8) | r) >>> 0;
}
