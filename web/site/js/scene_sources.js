// Where the "Many balls" page gets its world from. Each source builds a carom::web::DrawnWorld
// (a carom::World plus the shapes it was given, for drawing) from the page's controls.
//
// Scene files: a source that reads a carom scene (examples/*.json, or a file dropped on the
// page) fits here as one more entry whose build() turns the file's text into a DrawnWorld
// (through a binding to the scene loader, carom_scene). The page asks nothing else of a source.
export const BOX_SIZE = {x: 160, y: 100};

// Packing fraction of the generated box: dense enough for many collisions, loose enough that
// the lattice start melts within a few frames.
const PACKING_FRACTION = 0.25;

export const sceneSources = [
  {
    id: 'box',
    label: 'Box of N balls',
    usesControls: true,
    build: (carom, {count, speed, restitution}) => carom.DrawnWorld.filled_box({
      count, size: BOX_SIZE, packing_fraction: PACKING_FRACTION, speed, restitution, seed: 1,
    }),
  },
];
