// The Galton board's geometry, in units of the peg spacing, y up: what the "Galton board" page
// builds its world from and draws. Shapes and numbers only; the motion is carom's.
//
// Pegs sit on a triangular lattice across the board: rows √3/2 apart, each shifted half a spacing
// from the one above, so that every peg has two pegs of the next row equally far below it on
// either side. Balls enter through a hopper's outlet straight above the top row's middle peg. A
// ball that meets one peg a row and passes it on the left or the right with even chances has, after
// n rows, made n such choices; the channel it leaves by, counted from the left, is how many times
// it went right: Binomial(n, 1/2) over the n + 1 channels under the middle peg's cone. One bin
// under each channel catches it (the board is exactly that wide).
//
// Where a row would put a peg so close to the box's side that a ball could wedge between them, it
// has none; where the side falls on a lattice site, half a peg (an arc) stands on it, so that a
// ball running down the side meets a peg a row like any other.

export const ROWS = 12;
const SPACING = 1;
const ROW_HEIGHT = SPACING * Math.sqrt(3) / 2;
export const PEG_RADIUS = 0.2;
// A gap between two pegs of a row is 0.6, twice a ball across: two balls arriving together do
// not wedge in it.
export const BALL_RADIUS = 0.15;
// Deep enough for the fullest bin of MAX_BALLS (measured: up to 119 balls, piled 12 high).
const BIN_DEPTH = 13;
// Between the last row of pegs and the dividers' tops (each divider stands under one of the last
// row's pegs), so that the last peg's deflection is over before a ball meets a divider.
const BIN_GAP = 0.6;
const HOPPER_HEIGHT = 4;
const POUR_HEADROOM = 1.5;  // above the hopper's rim, where balls are poured in
export const MAX_BALLS = 1000;

// Binomial(n, 1/2): the chance of each channel 0..n.
export function binomial(n) {
  let p = [1];
  for (let row = 0; row < n; ++row) {
    const next = new Array(p.length + 1).fill(0);
    p.forEach((value, k) => { next[k] += value / 2; next[k + 1] += value / 2; });
    p = next;
  }
  return p;
}

export function galtonBoard(rows = ROWS) {
  const half = (rows + 1) * SPACING / 2;  // the bins span the box: rows + 1 of them
  const binTop = BIN_DEPTH;
  const lastRowY = binTop + BIN_GAP;
  const rowY = (i) => lastRowY + (rows - 1 - i) * ROW_HEIGHT;
  const outletY = rowY(-1);
  const rimY = outletY + HOPPER_HEIGHT;
  const top = rimY + POUR_HEADROOM;

  const pegs = [];
  const arcs = [];
  for (let i = 0; i < rows; ++i) {
    // Row 0's middle peg is at x = 0: even rows on whole spacings, odd rows halfway between.
    const offset = i % 2 ? SPACING / 2 : 0;
    for (let x = offset - Math.floor(half / SPACING) * SPACING; x < half; x += SPACING) {
      const room = half - Math.abs(x) - PEG_RADIUS;  // between the peg and the side
      if (room > 2 * BALL_RADIUS) pegs.push({x, y: rowY(i)});
    }
    if (Math.abs(half - offset - Math.round((half - offset) / SPACING) * SPACING) < 1e-9) {
      arcs.push({center: {x: half, y: rowY(i)}, radius: PEG_RADIUS,
                 start_angle: Math.PI / 2, end_angle: 3 * Math.PI / 2});
      arcs.push({center: {x: -half, y: rowY(i)}, radius: PEG_RADIUS,
                 start_angle: -Math.PI / 2, end_angle: Math.PI / 2});
    }
  }
  const segments = [];
  // The hopper's sides, from its rim at the box's sides down to the outlet, one spacing wide.
  for (const side of [-1, 1]) {
    segments.push({a: {x: side * half, y: rimY}, b: {x: side * SPACING / 2, y: outletY}});
  }
  const edges = [];  // the bins' sides, left to right: the box's sides and the dividers
  for (let j = 0; j <= rows + 1; ++j) edges.push(-half + j * SPACING);
  for (const x of edges.slice(1, -1)) segments.push({a: {x, y: 0}, b: {x, y: binTop}});

  return {
    rows,
    lower: {x: -half, y: 0},
    upper: {x: half, y: top},
    pegs,
    pegRadius: PEG_RADIUS,
    ballRadius: BALL_RADIUS,
    segments,
    arcs,
    bins: {edges, top: binTop},
    // Where balls are poured in: over the outlet, narrower than it, so that a ball falls through
    // without touching the hopper (balls poured onto its sides overfill the middle bins;
    // docs/playground.md).
    pour: {x0: -(SPACING / 2 - 2 * BALL_RADIUS), x1: SPACING / 2 - 2 * BALL_RADIUS,
           y: rimY + POUR_HEADROOM / 2},
  };
}

// The bin (0 to rows) whose sides are either side of x.
export function binOf(board, x) {
  const {edges} = board.bins;
  const bin = Math.floor((x - edges[0]) / SPACING);
  return Math.min(edges.length - 2, Math.max(0, bin));
}
