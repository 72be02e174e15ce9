// carom internal: the collision filters of a world's balls and walls. Balls name their filter by
// a small number (kept in the spare bytes of their BallInfo), walls by a number each; number 0 is
// the default filter, so a world that never sets one reads no table. `active` is whether any
// ball or wall has ever had another filter: the engine asks the table only then.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "carom/filter.hpp"

namespace carom::detail {

class FilterTable {
 public:
  // The number of `filter`, added if new (filters are few: a game has a handful of kinds).
  std::uint32_t number_of(const CollisionFilter& filter) {
    if (filter == CollisionFilter{}) return 0;
    for (std::uint32_t k = 1; k < filters_.size(); ++k) {
      if (filters_[k] == filter) return k;
    }
    filters_.push_back(filter);
    active_ = true;
    return static_cast<std::uint32_t>(filters_.size() - 1);
  }
  [[nodiscard]] const CollisionFilter& operator[](std::uint32_t number) const {
    return filters_[number];
  }
  [[nodiscard]] bool meet(std::uint32_t a, std::uint32_t b) const {
    return should_collide(filters_[a], filters_[b]);
  }
  [[nodiscard]] bool active() const { return active_; }
  [[nodiscard]] std::size_t size() const { return filters_.size(); }
  // For loading: the table as it was saved (entry 0 the default).
  void assign(std::vector<CollisionFilter> filters) {
    filters_ = std::move(filters);
    if (filters_.empty()) filters_.push_back({});
    active_ = filters_.size() > 1;
  }
  [[nodiscard]] const std::vector<CollisionFilter>& all() const { return filters_; }

 private:
  std::vector<CollisionFilter> filters_{CollisionFilter{}};
  bool active_ = false;
};

}  // namespace carom::detail
