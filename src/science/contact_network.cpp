#include "carom/science/contact_network.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/number_text.hpp"
#include "neighbour_cells.hpp"

namespace carom::science {
namespace {

// The world's balls now, in handle order, in a cell list reaching `reach_factor` times the
// largest diameter.
struct Disks {
  std::vector<Vec2> positions;
  std::vector<double> radii;
  double largest = 0.0;
};

Disks disks_of(const World& world) {
  Disks disks;
  for (const BallId id : world.balls()) {
    disks.positions.push_back(world.position(id));
    disks.radii.push_back(world.radius(id));
    disks.largest = std::max(disks.largest, disks.radii.back());
  }
  return disks;
}

// The cell list over the world's cell (or, open, around its balls).
NeighbourCells cells_for(const World& world, const Disks& disks, double reach) {
  const WorldDef& def = world.def();
  Vec2 lower = def.lower;
  Vec2 upper = def.upper;
  if (def.boundary == Boundary::open) {
    lower = upper = disks.positions.empty() ? Vec2{} : disks.positions.front();
    for (const Vec2 p : disks.positions) {
      lower = {std::min(lower.x, p.x), std::min(lower.y, p.y)};
      upper = {std::max(upper.x, p.x), std::max(upper.y, p.y)};
    }
    upper += Vec2{reach, reach};
  }
  NeighbourCells cells(lower, upper, reach, def.boundary == Boundary::periodic,
                       disks.positions.size());
  for (std::uint32_t i = 0; i < disks.positions.size(); ++i) cells.insert(i, disks.positions[i]);
  return cells;
}

}  // namespace

ContactNetwork find_contact_network(const World& world, double tolerance) {
  if (!(std::isfinite(tolerance) && tolerance >= 0.0)) {
    throw InvalidArgument("science::find_contact_network", "tolerance", number_text(tolerance),
                          "must be a finite number >= 0");
  }
  const Disks disks = disks_of(world);
  const std::size_t n = disks.positions.size();
  ContactNetwork network;
  network.contacts.assign(n, 0);
  network.rattler.assign(n, 0);
  if (n == 0) return network;
  const double reach = 2.0 * disks.largest * (1.0 + tolerance);
  const NeighbourCells cells = cells_for(world, disks, reach);
  std::vector<std::vector<std::uint32_t>> touching(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    cells.for_each_near(disks.positions[i], [&](std::uint32_t j, Vec2 offset) {
      if (j <= i) return;
      const double sum = disks.radii[i] + disks.radii[j];
      const double gap = length(offset) - sum;
      if (gap <= tolerance * sum) {
        network.pairs.push_back({i, j});
        touching[i].push_back(j);
        touching[j].push_back(i);
      }
    });
  }
  std::sort(network.pairs.begin(), network.pairs.end(),
            [](const ContactNetwork::Pair& x, const ContactNetwork::Pair& y) {
              return x.a != y.a ? x.a < y.a : x.b < y.b;
            });
  std::vector<std::uint32_t> walls(n, 0);
  if (world.def().boundary == Boundary::box) {
    const Vec2 lower = world.def().lower;
    const Vec2 upper = world.def().upper;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 p = disks.positions[i];
      const double r = disks.radii[i];
      const double limit = r * (1.0 + tolerance);
      for (const double distance : {p.x - lower.x, upper.x - p.x, p.y - lower.y, upper.y - p.y}) {
        if (distance <= limit) ++walls[i];
      }
      network.wall_contacts += walls[i];
    }
  }
  double all = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    network.contacts[i] = static_cast<std::uint32_t>(touching[i].size()) + walls[i];
    all += network.contacts[i];
  }
  network.mean_contacts = all / static_cast<double>(n);

  // Rattlers: fewer than three contacts among the disks still counted, again and again.
  std::vector<std::uint32_t> left = network.contacts;
  std::vector<std::uint32_t> pending;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (left[i] < 3) {
      network.rattler[i] = 1;
      pending.push_back(i);
    }
  }
  while (!pending.empty()) {
    const std::uint32_t i = pending.back();
    pending.pop_back();
    for (const std::uint32_t j : touching[i]) {
      if (network.rattler[j] != 0) continue;
      if (--left[j] < 3) {
        network.rattler[j] = 1;
        pending.push_back(j);
      }
    }
  }
  double rest_contacts = 0.0;
  std::uint64_t rest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (network.rattler[i] != 0) {
      ++network.rattlers;
      continue;
    }
    ++rest;
    rest_contacts += left[i];
  }
  network.mean_contacts_of_rest = rest > 0 ? rest_contacts / static_cast<double>(rest) : 0.0;
  return network;
}

double global_psi6(const World& world, double cutoff) {
  if (!(std::isfinite(cutoff) && cutoff > 0.0)) {
    throw InvalidArgument("science::global_psi6", "cutoff", number_text(cutoff),
                          "must be a finite number > 0");
  }
  const Disks disks = disks_of(world);
  const std::size_t n = disks.positions.size();
  if (n == 0) return 0.0;
  const NeighbourCells cells = cells_for(world, disks, 2.0 * disks.largest * cutoff);
  std::complex<double> total;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::complex<double> local;
    int neighbours = 0;
    cells.for_each_near(disks.positions[i], [&](std::uint32_t j, Vec2 offset) {
      if (j == i) return;
      const double reach = cutoff * (disks.radii[i] + disks.radii[j]);
      if (length_squared(offset) >= reach * reach) return;
      local += std::polar(1.0, 6.0 * std::atan2(offset.y, offset.x));
      ++neighbours;
    });
    if (neighbours > 0) total += local / static_cast<double>(neighbours);
  }
  return std::abs(total) / static_cast<double>(n);
}

}  // namespace carom::science
