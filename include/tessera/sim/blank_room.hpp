#pragma once
// A room with nothing on its walls, for motion estimation from depth alone (fusion/depth_icp.hpp,
// issue 18 item 10): what a colour camera sees there is too plain for features (thesis section
// 5.2.3), so whether the motion can be solved depends only on the geometry in view. The views
// range from one plane (nothing pins the motion along it) to a corner with the floor and the
// ceiling (everything pinned).
//
// The room is 6 m x 5 m at 5 cm with one-cell walls (free space x in [0.05, 5.95], y in [0.05,
// 4.95]), walls 2.5 m high; the camera is the default Kinect v1 on the thesis' neck, 1.03 m up
// (sim/rgbd_camera.hpp), so the floor enters the view beyond 2.6 m and the ceiling beyond 3.7 m.
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/rgbd_camera.hpp"

namespace tessera {

struct BlankView {
  std::string name;  // "corner and floor (3.2 m)", ...
  Pose2 T_world_robot;
  /// True when the depth in view pins all six degrees of freedom of a small motion.
  bool solvable = false;
};

struct BlankRoom {
  RgbdCamera camera;
  /// A wall at 1.5 m (one plane), a wall and the floor at 3 m (two planes), the south-west corner
  /// at 1.5 m (two walls), the corner at 3.2 m (two walls and the floor) and at 4.2 m (two walls,
  /// the floor and the ceiling); the distances are along the optical axis to the wall or corner.
  std::vector<BlankView> views;
};

/// Input errors: invalid camera options (RgbdCamera::create's).
[[nodiscard]] Result<BlankRoom> make_blank_room(const RgbdCameraOptions& camera = {});

}  // namespace tessera
