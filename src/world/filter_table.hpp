// carom internal: the collision filters of a world's balls and walls. Balls name their filter by
// a small number (kept in the spare bytes of their BallInfo), walls by a number each; number 0 is
// the default filter, so a world that never sets one reads no table. `active` is whether any
// ball or wall has ever had another filter: the engine asks the table only then.
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

#include "carom/filter.hpp"

namespace carom::detail {

class FilterTable {
 public:
  // The number of `filter`, added if new (filters are few: a game has a handful of kinds).
  std::uint32_t number_of(const CollisionFilter& filter) {
    if (filter == CollisionFilter{}) return 0;
    // (By a map: a game may give every ragdoll a group of its own, thousands of filters.)
    const auto [at, added] =
        numbers_.try_emplace(key(filter), static_cast<std::uint32_t>(filters_.size()));
    if (added) {
      filters_.push_back(filter);
      active_ = true;
    }
    return at->second;
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
    numbers_.clear();
    for (std::uint32_t k = 1; k < filters_.size(); ++k) numbers_.try_emplace(key(filters_[k]), k);
    active_ = filters_.size() > 1;
  }
  [[nodiscard]] const std::vector<CollisionFilter>& all() const { return filters_; }

 private:
  using Key = std::tuple<std::uint64_t, std::uint64_t, std::int32_t>;
  static Key key(const CollisionFilter& f) { return {f.category, f.mask, f.group}; }

  std::vector<CollisionFilter> filters_{CollisionFilter{}};
  std::map<Key, std::uint32_t> numbers_;
  bool active_ = false;
};

}  // namespace carom::detail
