// The hard-disk science library: a gas of four disks in a periodic box, measured for a short
// run. Exits 0 when the measurement is a real one (collisions counted, a positive pressure).
#include <carom/science/block_average.hpp>
#include <carom/science/gas_monitor.hpp>
#include <carom/world.hpp>
#include <cstdio>

int main() {
  carom::WorldDef def;
  def.boundary = carom::Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {10.0, 10.0};
  carom::World world(def);
  world.add_ball({.position = {2.0, 2.0}, .velocity = {1.0, 0.3}, .radius = 1.0});
  world.add_ball({.position = {7.0, 2.5}, .velocity = {-0.7, 0.9}, .radius = 1.0});
  world.add_ball({.position = {3.0, 7.0}, .velocity = {0.4, -1.1}, .radius = 1.0});
  world.add_ball({.position = {7.5, 7.5}, .velocity = {-0.7, -0.1}, .radius = 1.0});
  const carom::science::GasResults gas = carom::science::measure_gas(world, 200.0, {.blocks = 4});
  std::printf("%llu collisions, Z = %g +- %g\n", static_cast<unsigned long long>(gas.collisions),
              gas.z.mean, gas.z.error);
  return gas.collisions > 0 && gas.z.mean > 1.0 && gas.z.blocks == 4 ? 0 : 1;
}
