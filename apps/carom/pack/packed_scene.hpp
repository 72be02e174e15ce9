// carom tool: what `carom pack` writes — the packing as a scene, and its picture with every disk
// coloured by its number of contacts and the contact network drawn over it.
#pragma once

#include <string>

#include "carom/scene.hpp"
#include "carom/science/contact_network.hpp"
#include "carom/world.hpp"

namespace carom::cli {

// The world as a scene: its cell, its balls (position, velocity, radius, mass) in handle order,
// and its growth from now (0 once a compression has ended). Loading it gives the same balls bit
// for bit (scenes round-trip every double exactly).
[[nodiscard]] Scene packed_scene(const World& world, const std::string& description);

// The picture (PNG, or SVG when the name ends in .svg) of the packing: rattlers grey, the rest
// coloured by contact number, each contact a line between the two centres.
[[nodiscard]] std::string packing_picture(const Scene& scene,
                                          const science::ContactNetwork& network,
                                          const std::string& title, const std::string& subtitle,
                                          bool svg);

}  // namespace carom::cli
