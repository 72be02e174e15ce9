// Filled discs written straight into the canvas's pixels. With thousands of balls this is much
// cheaper than asking the 2D context for one arc each: the cost is the pixels covered (a fixed
// fraction of the box at a given packing fraction), not a path per ball. Drawing only.
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

  // Every pixel whose centre lies inside the disc (pixel units) takes the colour.
  disc(x, y, r, colour) {
    const {width, height} = this.image;
    const top = Math.max(0, Math.ceil(y - r - 0.5));
    const bottom = Math.min(height - 1, Math.floor(y + r - 0.5));
    for (let row = top; row <= bottom; ++row) {
      const dy = row + 0.5 - y;
      const half = Math.sqrt(Math.max(0, r * r - dy * dy));
      const left = Math.max(0, Math.ceil(x - half - 0.5));
      const right = Math.min(width - 1, Math.floor(x + half - 0.5));
      if (left <= right) this.pixels.fill(colour, row * width + left, row * width + right + 1);
    }
  }

  end() { this.context.putImageData(this.image, 0, 0); }
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
