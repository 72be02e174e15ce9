// carom scenes internal: placing a generator's balls (lattice or random) and drawing their
// velocities. The method and its limits are in docs/scenes.md ("Generators").
#pragma once

#include <cstddef>
#include <vector>

#include "carom/scene.hpp"

namespace carom::scene_detail {

// Random sequential addition of equal disks jams at a packing fraction of about 0.547 (Feder
// 1980; Hinrichsen, Feder and Jøssang 1986); well before that each new disk needs very many
// tries. Random placement is refused above this fraction of the generator's own balls.
inline constexpr double kRandomPlacementLimit = 0.5;
// Tries per ball before random placement gives up.
inline constexpr int kRandomPlacementTries = 10'000;

// The balls of generator `index`, placed so as to overlap none of `existing` (the balls already
// placed, explicit or generated) nor each other. Throws PathedSceneError (generators[index]).
[[nodiscard]] std::vector<SceneBall> generate_balls(const Scene& scene, std::size_t index,
                                                    const std::vector<SceneBall>& existing);

}  // namespace carom::scene_detail
