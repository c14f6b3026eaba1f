#include "tessera/slam/submap.hpp"

#include <cmath>

namespace tessera::slam {

std::optional<std::string> validate(const SubmapOptions& o) {
  if (!(o.resolution_m > 0.0)) return "resolution_m must be > 0";
  if (o.scans_per_submap < 1) return "scans_per_submap must be >= 1";
  if (!(o.travel_per_submap_m >= 0.0)) return "travel_per_submap_m must be >= 0";
  if (!(o.initial_size_m > 0.0)) return "initial_size_m must be > 0";
  return validate(o.insert);
}

namespace {

GridGeometry initial_geometry(const SubmapOptions& options) {
  const int side =
      std::max(2, static_cast<int>(std::ceil(options.initial_size_m / options.resolution_m)));
  const double half_m = 0.5 * side * options.resolution_m;
  return GridGeometry({-half_m, -half_m}, options.resolution_m, side, side);
}

}  // namespace

Submap::Submap(const Pose2& T_local_submap, const SubmapOptions& options)
    : T_local_submap_(T_local_submap), grid_(initial_geometry(options)) {}

void Submap::insert(const ScanPoints& points, const Pose2& T_local_robot,
                    const RangeInserter& inserter) {
  TESSERA_ASSERT(!finished_);
  inserter.insert(grid_, between(T_local_submap_, T_local_robot), points);
  const Vec2 position = T_local_robot.translation();
  if (num_scans_ > 0) travel_m_ += (position - last_position_m_).norm();
  last_position_m_ = position;
  ++num_scans_;
}

ActiveSubmaps::ActiveSubmaps(const SubmapOptions& options)
    : options_(options), inserter_(options.insert) {}

ActiveSubmaps::Insertion ActiveSubmaps::insert(const ScanPoints& points,
                                               const Pose2& T_local_robot) {
  Insertion out;
  if (active_.empty() || full(submap(active_.back()))) {
    // The oldest active submap was finished when the newest became full; it leaves the window
    // when the new one enters.
    if (active_.size() >= 2) active_.erase(active_.begin());
    submaps_.emplace_back(Pose2{T_local_robot.x, T_local_robot.y, 0.0}, options_);
    active_.push_back(static_cast<int>(submaps_.size()) - 1);
  }
  for (const int id : active_) {
    submaps_[static_cast<std::size_t>(id)].insert(points, T_local_robot, inserter_);
    out.inserted_into.push_back(id);
  }
  Submap& oldest = submaps_[static_cast<std::size_t>(active_.front())];
  if (active_.size() >= 2 && !oldest.finished() && full(submap(active_.back()))) {
    oldest.finish();
    out.finished = active_.front();
  }
  return out;
}

bool ActiveSubmaps::full(const Submap& s) const {
  return s.num_scans() >= options_.scans_per_submap ||
         (options_.travel_per_submap_m > 0.0 && s.travel_m() >= options_.travel_per_submap_m);
}

std::vector<int> ActiveSubmaps::finish_all() {
  std::vector<int> finished;
  for (const int id : active_) {
    Submap& s = submaps_[static_cast<std::size_t>(id)];
    if (s.finished()) continue;
    s.finish();
    finished.push_back(id);
  }
  active_.clear();
  return finished;
}

std::optional<int> ActiveSubmaps::matching_id() const {
  if (active_.empty()) return std::nullopt;
  return active_.front();
}

}  // namespace tessera::slam
