// The pinball table's geometry, y up, in units of a ball's diameter (a real ball is 27 mm
// across, so the table is 54 cm by 97 cm): what the "Pinball" page builds its world from and
// draws. Shapes and numbers only; the motion is carom's.
//
// A box holds it all. The plunger's lane runs up the right side behind a wall; at the top two
// rounded corners (quarter circles, as short segments) turn a launched ball left across the
// table. Below: three round bumpers and three posts (immovable balls), two triangular slingshots,
// two slanted walls that lead down to the flippers, and between the flippers' tips the gap to the
// drain. Two rollover lanes between the top posts are sensors: a ball passing one scores. The
// flippers are given at rest, each from its pivot (a, its outer end, where the slanted wall
// meets it) to its tip (b); the page swings them up by FLIPPER_SWING about the pivot (the left
// counter-clockwise, the right clockwise) and back.

export const WIDTH = 20;
export const HEIGHT = 36;
export const LANE_X = 18.5;  // the plunger lane's inner wall; the lane is the strip right of it
export const BALL_RADIUS = 0.5;
// The drain: a sensor along this line, left of the lane, removes the ball that reaches it.
export const DRAIN_Y = 2;
// The angle between a flipper's rest and its up stop, in radians: from 24° below the horizontal
// to 24° above, the tip rising by 2.6 ball diameters.
export const FLIPPER_SWING = 0.84;
const CORNER_RADIUS = 5;
const CORNER_SEGMENTS = 8;  // short enough that the bend reads as a curve

// A quarter circle from angle `from` to `to` as a chain of segments.
function corner(center, from, to) {
  const points = [];
  for (let k = 0; k <= CORNER_SEGMENTS; ++k) {
    const angle = from + (to - from) * k / CORNER_SEGMENTS;
    points.push({x: center.x + CORNER_RADIUS * Math.cos(angle),
                 y: center.y + CORNER_RADIUS * Math.sin(angle)});
  }
  return chain(points);
}

function chain(points, closed = false) {
  const segments = [];
  for (let k = 0; k + 1 < points.length; ++k) segments.push({a: points[k], b: points[k + 1]});
  if (closed) segments.push({a: points[points.length - 1], b: points[0]});
  return segments;
}

export function pinballTable() {
  const middle = LANE_X / 2;  // the playfield's middle line
  // Mirror of a point across the playfield's middle line.
  const mirror = (p) => ({x: LANE_X - p.x, y: p.y});
  const slingshot = [{x: 2.5, y: 13}, {x: 2.5, y: 9.8}, {x: 5.2, y: 8.1}];
  const slope = [{x: 0, y: 10}, {x: 5.5, y: 5}];  // the left wall down to the left flipper
  const flipper = {a: {x: 5.5, y: 5}, b: {x: middle - 0.85, y: 3.7}};
  const walls = [
    {a: {x: LANE_X, y: 0}, b: {x: LANE_X, y: 26}},
    ...corner({x: CORNER_RADIUS, y: HEIGHT - CORNER_RADIUS}, Math.PI / 2, Math.PI),
    ...corner({x: WIDTH - CORNER_RADIUS, y: HEIGHT - CORNER_RADIUS}, 0, Math.PI / 2),
    ...chain(slope), ...chain(slope.map(mirror)),
    ...chain(slingshot, true), ...chain(slingshot.map(mirror), true),
  ];
  const bumpers = [{x: middle - 3.5, y: 25}, {x: middle + 3.5, y: 25}, {x: middle, y: 20.5}]
      .map((p) => ({...p, radius: 1.4}));
  const posts = [-2, 0, 2].map((dx) => ({x: middle + dx, y: 31, radius: 0.35}));
  // Across the gaps between the posts, a post's radius clear of each.
  const rollovers = [-1, 1].map((side) => ({
    a: {x: middle + side * 0.35, y: 31}, b: {x: middle + side * 1.65, y: 31}}));
  return {
    lower: {x: 0, y: 0},
    upper: {x: WIDTH, y: HEIGHT},
    walls,
    flippers: [flipper, {a: mirror(flipper.a), b: mirror(flipper.b)}],
    bumpers,
    posts,
    rollovers,
    drainLine: {a: {x: 0, y: DRAIN_Y}, b: {x: LANE_X, y: DRAIN_Y}},
    // Drawn under the flippers' gap; a ball there is taken out (DRAIN_Y).
    drain: [{x: middle - 2.2, y: 0}, {x: middle + 2.2, y: 0}, {x: middle + 2.2, y: DRAIN_Y},
            {x: middle - 2.2, y: DRAIN_Y}],
    // Where a launched ball starts: at the lane's foot, clear of the floor (a ball placed exactly
    // touching it could be refused for the rounding of its place).
    plunger: {x: (LANE_X + WIDTH) / 2, y: BALL_RADIUS + 0.1},
  };
}
