#pragma once
// The three-state robot process loop of the Fusion SLAM thesis, section 4.3.4: LEARN (the operator
// drives the robot and it maps), NAVIGATE (go to a commanded grid cell over the wavefront path,
// section 4.3.5) and FIND NODE (in the current cell: drive to a stored image node's pose, turn the
// neck to its heading, confirm by matching; section 4.3.4 and the experiment of Table 5.1 step 8).
// Commands come from the operator ("experiment call-back"); progress events come from the caller's
// mission loop, which owns the map, the planner and the follower. This class only decides states:
// no I/O, no clock. Reactive avoidance (nav/reactive_avoidance.hpp) runs in every state.
#include <cstddef>
#include <string>
#include <variant>

namespace tessera {

enum class ProcessState { kLearn, kNavigate, kFindNode };

/// The steps of FIND NODE, in order.
enum class FindNodePhase { kDriveToNodePose, kTurnNeck, kConfirm };

[[nodiscard]] const char* to_string(ProcessState s);
[[nodiscard]] const char* to_string(FindNodePhase p);

namespace process_event {
/// Operator: go to this grid cell. Accepted in every state (a new goal replaces the old one).
struct GoToCell {
  std::size_t cell = 0;
};
/// Operator: find this image node. The caller says whether the node is stored in the robot's
/// current cell; if not, the command is refused and the state does not change (the thesis shows
/// "cannot be found" on the robot's screen).
struct FindImageNode {
  std::size_t node = 0;
  bool in_current_cell = false;
};
/// Operator: stop and go back to learning (manual driving).
struct Stop {};
/// Mission loop, NAVIGATE: the robot is in the goal cell.
struct GoalCellReached {};
/// Mission loop, NAVIGATE: the wavefront gives no path from the current cell to the goal.
struct NoPath {};
/// Mission loop, FIND NODE: the robot is at the node's pose / the neck faces the node's heading.
struct NodePoseReached {};
struct NeckAligned {};
/// Mission loop, FIND NODE: matching the current view with the node succeeded or failed.
struct NodeConfirmed {};
struct NodeNotConfirmed {};
}  // namespace process_event

using ProcessEvent =
    std::variant<process_event::GoToCell, process_event::FindImageNode, process_event::Stop,
                 process_event::GoalCellReached, process_event::NoPath,
                 process_event::NodePoseReached, process_event::NeckAligned,
                 process_event::NodeConfirmed, process_event::NodeNotConfirmed>;

/// What handle() did. accepted is false when the event does not apply in the state it arrived in;
/// `note` then says why ("goal_cell_reached ignored in state learn").
struct ProcessTransition {
  ProcessState from = ProcessState::kLearn;
  ProcessState to = ProcessState::kLearn;
  bool accepted = false;
  std::string note;
};

class ProcessStateMachine {
 public:
  /// Starts in LEARN, as the thesis' robot does (it must be taught first).
  ProcessStateMachine() = default;

  ProcessTransition handle(const ProcessEvent& event);

  [[nodiscard]] ProcessState state() const { return state_; }
  /// Meaningful in NAVIGATE: the commanded cell.
  [[nodiscard]] std::size_t goal_cell() const { return goal_cell_; }
  /// Meaningful in FIND NODE: the image node searched for, and the step reached.
  [[nodiscard]] std::size_t target_node() const { return target_node_; }
  [[nodiscard]] FindNodePhase find_phase() const { return phase_; }
  /// Outcome of the last finished FIND NODE (true when confirmed).
  [[nodiscard]] bool last_search_succeeded() const { return last_search_succeeded_; }
  /// Outcome of the last finished NAVIGATE (true when the goal cell was reached).
  [[nodiscard]] bool last_navigation_succeeded() const { return last_navigation_succeeded_; }

 private:
  ProcessTransition go(ProcessState to, std::string note);
  ProcessTransition refuse(std::string note) const;

  ProcessState state_ = ProcessState::kLearn;
  std::size_t goal_cell_ = 0;
  std::size_t target_node_ = 0;
  FindNodePhase phase_ = FindNodePhase::kDriveToNodePose;
  bool last_search_succeeded_ = false;
  bool last_navigation_succeeded_ = false;
};

}  // namespace tessera
