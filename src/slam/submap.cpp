#include "tessera/slam/submap.hpp"

#include <algorithm>
#include <cmath>

namespace tessera::slam {

std::optional<std::string> validate(const SubmapOptions& o) {
  if (!(o.resolution_m > 0.0)) return "resolution_m must be > 0";
  if (o.scans_per_submap < 1) return "scans_per_submap must be >= 1";
  if (!(o.travel_per_submap_m >= 0.0)) return "travel_per_submap_m must be >= 0";
  if (!(o.initial_size_m > 0.0)) return "initial_size_m must be > 0";
  if (!(o.hit_evidence_step_m > 0.0)) return "hit_evidence_step_m must be > 0";
  if (!(o.max_hit_evidence_scale >= 1.0 && o.max_hit_evidence_scale <= 8.0)) {
    return "max_hit_evidence_scale must be in [1, 8]";
  }
  return validate(o.insert);
}

namespace {

/// The step that weighs a scan's hits is the mean over this many recent inserts.
constexpr std::size_t kRecentSteps = 20;

/// Evidence scales are rounded to this step, one inserter (with its tables) per step.
constexpr double kEvidenceScaleStep = 0.25;

/// The hit probability whose log-odds are `scale` times those of `p`.
double scaled_probability(double p, double scale) {
  const double log_odds = scale * std::log(p / (1.0 - p));
  return 1.0 / (1.0 + std::exp(-log_odds));
}

std::vector<RangeInserter> make_inserters(const SubmapOptions& options) {
  const auto levels = static_cast<int>(
      1 + std::lround((options.max_hit_evidence_scale - 1.0) / kEvidenceScaleStep));
  std::vector<RangeInserter> inserters;
  inserters.reserve(static_cast<std::size_t>(levels));
  for (int k = 0; k < levels; ++k) {
    RangeInsertOptions insert = options.insert;
    insert.hit_probability =
        scaled_probability(options.insert.hit_probability, 1.0 + k * kEvidenceScaleStep);
    inserters.emplace_back(insert);
  }
  return inserters;
}

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
    : options_(options), inserters_(make_inserters(options)) {}

const RangeInserter& ActiveSubmaps::inserter_for(double step_m) const {
  const double scale =
      std::clamp(step_m / options_.hit_evidence_step_m, 1.0, options_.max_hit_evidence_scale);
  const auto k = static_cast<std::size_t>(std::lround((scale - 1.0) / kEvidenceScaleStep));
  return inserters_[std::min(k, inserters_.size() - 1)];
}

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
  const Vec2 position = T_local_robot.translation();
  if (last_position_m_) {
    recent_steps_m_.push_back((position - *last_position_m_).norm());
    if (recent_steps_m_.size() > kRecentSteps) recent_steps_m_.pop_front();
  }
  last_position_m_ = position;
  double mean_step_m = 0.0;
  for (const double step_m : recent_steps_m_) mean_step_m += step_m;
  if (!recent_steps_m_.empty()) mean_step_m /= static_cast<double>(recent_steps_m_.size());
  const RangeInserter& inserter = inserter_for(mean_step_m);
  for (const int id : active_) {
    submaps_[static_cast<std::size_t>(id)].insert(points, T_local_robot, inserter);
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
  last_position_m_.reset();
  return finished;
}

std::optional<int> ActiveSubmaps::matching_id() const {
  if (active_.empty()) return std::nullopt;
  return active_.front();
}

}  // namespace tessera::slam
