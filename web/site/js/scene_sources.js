// Where the "Many balls" page gets its world from. Each source builds a carom::web::DrawnWorld
// (a carom::World plus the shapes it was given, for drawing) from the page's controls; the page
// asks nothing else of a source, and draws whatever walls and arcs the world holds.
//
// Scene files (examples/*.json, or a file dropped on the page or chosen with the file picker)
// are sources too: sceneFileSource below. See docs/playground.md.
const BOX_SIZE = {x: 160, y: 100};

// Packing fraction of the generated balls: dense enough for many collisions, loose enough that
// the lattice start melts within a few frames.
const PACKING_FRACTION = 0.25;

// Three or more inelastic balls can collide infinitely often in finite time; carom's TC model
// makes a ball that collided less than this long ago bounce elastically. The balls' mean free
// time here is of order radius / speed ~ 10⁻², so 10⁻⁴ leaves the dissipation almost untouched.
const COLLAPSE_TIME = 1e-4;

// A funnel of two segments narrowing downwards, three round bumpers (full-circle arcs) below
// it, and a cup (the lower half of an arc) above it; y up, as every scene is drawn.
const FUNNEL = [{a: {x: 15, y: 75}, b: {x: 68, y: 50}}, {a: {x: 145, y: 75}, b: {x: 92, y: 50}}];
const BUMPERS = [{x: 35, y: 25}, {x: 80, y: 20}, {x: 125, y: 25}].map(
    (center) => ({center, radius: 7, start_angle: 0, end_angle: 2 * Math.PI}));
const CUP = {center: {x: 80, y: 78}, radius: 12, start_angle: Math.PI, end_angle: 2 * Math.PI};

function boxWorld(carom, restitution) {
  return new carom.DrawnWorld({boundary: carom.Boundary.box, lower: {x: 0, y: 0},
                               upper: BOX_SIZE, restitution, collapse_time: COLLAPSE_TIME,
                               cell_size: 0, gravity: {x: 0, y: 0}, rest_height: 1e-3});
}

// Builds with fill(world); a world left half-built by an error is freed, not leaked.
function built(world, fill) {
  try {
    fill(world);
    return world;
  } catch (error) {
    world.delete();
    throw error;
  }
}

function lattice(world, {count, speed}) {
  world.fill_lattice({count, packing_fraction: PACKING_FRACTION, speed, seed: 1});
}

export const sceneSources = [
  {
    id: 'box',
    label: 'Box of N balls',
    build: (carom, controls) => built(boxWorld(carom, controls.restitution),
                                      (world) => lattice(world, controls)),
  },
  {
    id: 'obstacles',
    label: 'Box with walls and arcs',
    build: (carom, controls) => built(boxWorld(carom, controls.restitution), (world) => {
      for (const segment of FUNNEL) world.add_segment(segment);
      for (const arc of [...BUMPERS, CUP]) world.add_arc(arc);
      lattice(world, controls);  // sites on a wall stay empty
    }),
  },
];

// ---- scene files ---------------------------------------------------------------------------

// A scene file as a source: its text is read once (load), then carom's scene library
// (carom.load_scene: parse_scene + make_world) builds the world; the scene sets the number of
// balls, their speeds and the restitution, so the page's N and e sliders do not apply.
export function sceneFileSource(id, label, name, readText) {
  let text = null;
  return {
    id,
    label,
    fromFile: true,
    async load() {
      if (text === null) text = await readText();
    },
    build: (carom) => carom.load_scene(text, name),
  };
}

// The examples the wasm build copies beside the pages (site/examples/, listed in index.json).
export async function exampleSources() {
  const response = await fetch('examples/index.json');
  if (!response.ok) throw new Error(`examples/index.json: HTTP ${response.status}`);
  const names = await response.json();
  return names.map((name) => sceneFileSource(`example:${name}`, `Example: ${name}`, name,
                                             async () => {
    const file = await fetch(`examples/${name}`);
    if (!file.ok) throw new Error(`examples/${name}: HTTP ${file.status}`);
    return file.text();
  }));
}
