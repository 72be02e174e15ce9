#include "engine.hpp"

#include <stdexcept>

namespace carom::peers {

std::vector<EngineInfo> available_engines() {
  std::vector<EngineInfo> engines{{"carom", CAROM_PEERS_CAROM_VERSION}};
#if CAROM_PEERS_BOX2D
  engines.push_back({"box2d", box2d_version()});
#endif
#if CAROM_PEERS_CHIPMUNK
  engines.push_back({"chipmunk", chipmunk_version()});
#endif
  return engines;
}

std::unique_ptr<Engine> make_engine(std::string_view name, const Scene& scene) {
  if (name == "carom") return make_carom_engine(scene);
#if CAROM_PEERS_BOX2D
  if (name == "box2d") return make_box2d_engine(scene);
#endif
#if CAROM_PEERS_CHIPMUNK
  if (name == "chipmunk") return make_chipmunk_engine(scene);
#endif
  std::string known;
  for (const EngineInfo& engine : available_engines()) known += " " + engine.name;
  throw std::invalid_argument("unknown engine '" + std::string(name) +
                              "'; this build has:" + known);
}

}  // namespace carom::peers
