#include "tessera/nav/process_state_machine.hpp"

#include <type_traits>
#include <utility>

namespace tessera {

const char* to_string(ProcessState s) {
  switch (s) {
    case ProcessState::kLearn:
      return "learn";
    case ProcessState::kNavigate:
      return "navigate";
    case ProcessState::kFindNode:
      return "find_node";
  }
  return "unknown";
}

const char* to_string(FindNodePhase p) {
  switch (p) {
    case FindNodePhase::kDriveToNodePose:
      return "drive_to_node_pose";
    case FindNodePhase::kTurnNeck:
      return "turn_neck";
    case FindNodePhase::kConfirm:
      return "confirm";
  }
  return "unknown";
}

ProcessTransition ProcessStateMachine::go(ProcessState to, std::string note) {
  ProcessTransition t{state_, to, true, std::move(note)};
  state_ = to;
  return t;
}

ProcessTransition ProcessStateMachine::refuse(std::string note) const {
  return {state_, state_, false, std::move(note)};
}

ProcessTransition ProcessStateMachine::handle(const ProcessEvent& event) {
  namespace ev = process_event;
  const auto ignored = [this](const char* what) {
    return refuse(std::string(what) + " ignored in state " + to_string(state_));
  };
  return std::visit(
      [&](const auto& e) -> ProcessTransition {
        using E = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<E, ev::GoToCell>) {
          goal_cell_ = e.cell;
          return go(ProcessState::kNavigate, "navigate to cell " + std::to_string(e.cell));
        } else if constexpr (std::is_same_v<E, ev::FindImageNode>) {
          if (!e.in_current_cell) {
            return refuse("image node " + std::to_string(e.node) +
                          " is not stored in the current cell");
          }
          target_node_ = e.node;
          phase_ = FindNodePhase::kDriveToNodePose;
          return go(ProcessState::kFindNode, "find image node " + std::to_string(e.node));
        } else if constexpr (std::is_same_v<E, ev::Stop>) {
          return go(ProcessState::kLearn, "stopped by the operator");
        } else if constexpr (std::is_same_v<E, ev::GoalCellReached>) {
          if (state_ != ProcessState::kNavigate) return ignored("goal_cell_reached");
          last_navigation_succeeded_ = true;
          return go(ProcessState::kLearn, "reached cell " + std::to_string(goal_cell_));
        } else if constexpr (std::is_same_v<E, ev::NoPath>) {
          if (state_ != ProcessState::kNavigate) return ignored("no_path");
          last_navigation_succeeded_ = false;
          return go(ProcessState::kLearn, "no path to cell " + std::to_string(goal_cell_));
        } else if constexpr (std::is_same_v<E, ev::NodePoseReached>) {
          if (state_ != ProcessState::kFindNode || phase_ != FindNodePhase::kDriveToNodePose) {
            return ignored("node_pose_reached");
          }
          phase_ = FindNodePhase::kTurnNeck;
          return {state_, state_, true,
                  "at the pose of image node " + std::to_string(target_node_)};
        } else if constexpr (std::is_same_v<E, ev::NeckAligned>) {
          if (state_ != ProcessState::kFindNode || phase_ != FindNodePhase::kTurnNeck) {
            return ignored("neck_aligned");
          }
          phase_ = FindNodePhase::kConfirm;
          return {state_, state_, true, "facing image node " + std::to_string(target_node_)};
        } else if constexpr (std::is_same_v<E, ev::NodeConfirmed>) {
          if (state_ != ProcessState::kFindNode || phase_ != FindNodePhase::kConfirm) {
            return ignored("node_confirmed");
          }
          last_search_succeeded_ = true;
          return go(ProcessState::kLearn, "found image node " + std::to_string(target_node_));
        } else {
          static_assert(std::is_same_v<E, ev::NodeNotConfirmed>);
          if (state_ != ProcessState::kFindNode || phase_ != FindNodePhase::kConfirm) {
            return ignored("node_not_confirmed");
          }
          last_search_succeeded_ = false;
          return go(ProcessState::kLearn,
                    "image node " + std::to_string(target_node_) + " not confirmed");
        }
      },
      event);
}

}  // namespace tessera
