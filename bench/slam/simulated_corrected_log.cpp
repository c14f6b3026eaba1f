// A "corrected" CARMEN log of a simulated run, for issue 12's protocol on buildings that have no
// real log: the robot of sim/laser_run drives a covering tour of a floor plan with a SICK-class
// front laser (181 beams over 180 degrees, 1 cm noise), and the scans are kept as GMapping keeps
// them when it writes a corrected log (one whenever the robot has moved 1 m or turned 0.5 rad
// since the last, its linearUpdate and angularUpdate defaults), each with its TRUE pose. So the
// file is what the Radish corrected logs are, with a truth that is exact instead of GMapping's,
// and ../shared/tools/perturb_carmen.py gives it a drifting odometry the same way
// (scripts/slam_log_table.py --sim runs the whole protocol).
//
// usage: simulated_corrected_log --world FILE [--map-resolution-m R] --out FILE.log
//          [--seed N] [--max-path-m L] [--range-m 50] [--every-m 1.0] [--every-rad 0.5]
//          [--waypoint-spacing-m 3.5]
// Prints the scans kept, the path and the time driven. Exit 2 on a usage error, 3 on bad input
// (the floor plan, or no room for the robot), 4 when the log cannot be written.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "tessera/core/angle.hpp"
#include "tessera/io/carmen_log_writer.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {
namespace {

int usage(const char* message) {
  std::fprintf(stderr, "simulated_corrected_log: %s\n", message);
  return 2;
}

int run(int argc, char** argv) {
  std::optional<std::filesystem::path> world_path, out_path;
  MapLoadOptions load;
  std::uint64_t seed = 1;
  LaserRunOptions o;
  o.max_duration_s = 0.0;  // the whole tour unless --max-path-m
  o.max_speed_m_per_s = 0.6;
  o.scan_rate_hz = 5.0;
  o.lidar = LidarOptions{.beams = 181,
                         .fov_rad = std::numbers::pi,
                         .min_range_m = 0.0,
                         .max_range_m = 50.0,
                         .range_noise_stddev_m = 0.01};
  double every_m = 1.0, every_rad = 0.5;
  for (int i = 1; i < argc; i += 2) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return usage((arg + " needs a value").c_str());
    const char* value = argv[i + 1];
    if (arg == "--world") {
      world_path = value;
    } else if (arg == "--map-resolution-m") {
      load.resolution_m = std::atof(value);
    } else if (arg == "--out") {
      out_path = value;
    } else if (arg == "--seed") {
      seed = std::strtoull(value, nullptr, 10);
    } else if (arg == "--max-path-m") {
      o.max_path_length_m = std::atof(value);
    } else if (arg == "--range-m") {
      o.lidar.max_range_m = std::atof(value);
    } else if (arg == "--every-m") {
      every_m = std::atof(value);
    } else if (arg == "--every-rad") {
      every_rad = std::atof(value);
    } else if (arg == "--waypoint-spacing-m") {
      o.tour.waypoint_spacing_m = std::atof(value);
    } else {
      return usage(("unknown option " + arg).c_str());
    }
  }
  if (!world_path || !out_path) return usage("--world and --out are required");

  Result<LoadedMap> map = load_map(*world_path, load);
  if (!map) {
    std::fprintf(stderr, "simulated_corrected_log: %s\n", map.error().message.c_str());
    return map.error().kind == ErrorKind::kUsage ? 2 : 3;
  }
  const World world = World::from_map(map->map, 0.5, world_path->string());
  Result<SimulatedLaserRun> sim = simulate_laser_run(world, o, seed);
  if (!sim) {
    std::fprintf(stderr, "simulated_corrected_log: %s\n", sim.error().message.c_str());
    return 3;
  }

  // GMapping's processing rule: a scan is kept once the robot has moved every_m or turned
  // every_rad since the last kept one; the kept scans carry their true pose.
  LaserLog corrected;
  std::optional<Pose2> last;
  for (std::size_t i = 0; i < sim->log.scans.size(); ++i) {
    const Pose2& truth = sim->truth[i].pose;
    if (last) {
      const Pose2 d = between(*last, truth);
      if (std::hypot(d.x, d.y) < every_m && std::abs(normalize_angle(d.theta)) < every_rad) {
        continue;
      }
    }
    StampedScan s = sim->log.scans[i];
    s.odometry = truth;
    corrected.scans.push_back(std::move(s));
    last = truth;
  }
  if (Status s = write_carmen_log(*out_path, corrected); !s) {
    std::fprintf(stderr, "simulated_corrected_log: %s\n", s.error().message.c_str());
    return 4;
  }
  std::printf("%s: %zu scans of %zu kept, path %.0f m, %.0f s driven, tour %s\n",
              out_path->string().c_str(), corrected.scans.size(), sim->log.scans.size(),
              sim->path_length_m, sim->duration_s, sim->tour_completed ? "completed" : "cut short");
  return 0;
}

}  // namespace
}  // namespace tessera

int main(int argc, char** argv) { return tessera::run(argc, argv); }
