// A scene read from JSON text and run: two balls meeting head-on. Exits 0 when the answer is right.
#include <carom/scene.hpp>
#include <cstdio>

int main() {
  const carom::Scene scene = carom::parse_scene(R"({
    "balls": [{"position": [0, 0], "velocity": [8, 0], "radius": 1},
              {"position": [10, 0], "velocity": [-8, 0], "radius": 1}]})");
  carom::SceneWorld built = carom::make_world(scene);
  std::vector<carom::ContactEvent> contacts;
  carom::step_scene(built, 1.0, &contacts);
  // Centres 10 apart close at 16 per time unit and touch at distance 2: t = 0.5.
  std::printf("%zu contact at t = %g\n", contacts.size(),
              contacts.empty() ? -1.0 : contacts[0].time);
  return contacts.size() == 1 && contacts[0].time == 0.5 ? 0 : 1;
}
