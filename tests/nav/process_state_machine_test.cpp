#include "tessera/nav/process_state_machine.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tessera {
namespace {

namespace ev = process_event;
using ::testing::HasSubstr;

TEST(ProcessStateMachine, StartsLearningAndTheThesisExperimentRunsLearnNavigateFindLearn) {
  ProcessStateMachine m;
  EXPECT_EQ(m.state(), ProcessState::kLearn);
  // Table 5.1 step 8: navigate to the goal cell, then find the image node there.
  ProcessTransition t = m.handle(ev::GoToCell{42});
  EXPECT_TRUE(t.accepted);
  EXPECT_EQ(t.from, ProcessState::kLearn);
  EXPECT_EQ(t.to, ProcessState::kNavigate);
  EXPECT_EQ(m.goal_cell(), 42u);
  t = m.handle(ev::GoalCellReached{});
  EXPECT_EQ(t.to, ProcessState::kLearn);
  EXPECT_TRUE(m.last_navigation_succeeded());
  t = m.handle(ev::FindImageNode{7, true});
  EXPECT_EQ(t.to, ProcessState::kFindNode);
  EXPECT_EQ(m.target_node(), 7u);
  EXPECT_EQ(m.find_phase(), FindNodePhase::kDriveToNodePose);
  EXPECT_TRUE(m.handle(ev::NodePoseReached{}).accepted);
  EXPECT_EQ(m.find_phase(), FindNodePhase::kTurnNeck);
  EXPECT_TRUE(m.handle(ev::NeckAligned{}).accepted);
  EXPECT_EQ(m.find_phase(), FindNodePhase::kConfirm);
  EXPECT_EQ(m.state(), ProcessState::kFindNode);
  t = m.handle(ev::NodeConfirmed{});
  EXPECT_EQ(t.to, ProcessState::kLearn);
  EXPECT_TRUE(m.last_search_succeeded());
}

TEST(ProcessStateMachine, FindingANodeNotInTheCurrentCellIsRefusedAndTheStateKept) {
  ProcessStateMachine m;
  const ProcessTransition t = m.handle(ev::FindImageNode{3, false});
  EXPECT_FALSE(t.accepted);
  EXPECT_EQ(m.state(), ProcessState::kLearn);
  EXPECT_THAT(t.note, HasSubstr("not stored in the current cell"));
}

TEST(ProcessStateMachine, ProgressEventsOutOfTheirStateOrPhaseAreIgnoredWithAReason) {
  ProcessStateMachine m;
  ProcessTransition t = m.handle(ev::GoalCellReached{});
  EXPECT_FALSE(t.accepted);
  EXPECT_THAT(t.note, HasSubstr("ignored in state learn"));
  (void)m.handle(ev::FindImageNode{1, true});
  t = m.handle(ev::NodeConfirmed{});  // still driving to the pose: too early
  EXPECT_FALSE(t.accepted);
  EXPECT_EQ(m.state(), ProcessState::kFindNode);
  EXPECT_FALSE(m.handle(ev::NeckAligned{}).accepted);
  EXPECT_FALSE(m.handle(ev::NoPath{}).accepted);
}

TEST(ProcessStateMachine, NoPathAndNotConfirmedReturnToLearningAsFailures) {
  ProcessStateMachine m;
  (void)m.handle(ev::GoToCell{5});
  ProcessTransition t = m.handle(ev::NoPath{});
  EXPECT_EQ(t.to, ProcessState::kLearn);
  EXPECT_THAT(t.note, HasSubstr("no path to cell 5"));
  EXPECT_FALSE(m.last_navigation_succeeded());
  (void)m.handle(ev::FindImageNode{2, true});
  (void)m.handle(ev::NodePoseReached{});
  (void)m.handle(ev::NeckAligned{});
  t = m.handle(ev::NodeNotConfirmed{});
  EXPECT_EQ(t.to, ProcessState::kLearn);
  EXPECT_FALSE(m.last_search_succeeded());
}

TEST(ProcessStateMachine, ANewGoalOrStopIsObeyedInEveryState) {
  ProcessStateMachine m;
  (void)m.handle(ev::FindImageNode{2, true});
  ProcessTransition t = m.handle(ev::GoToCell{9});
  EXPECT_EQ(t.from, ProcessState::kFindNode);
  EXPECT_EQ(t.to, ProcessState::kNavigate);
  t = m.handle(ev::GoToCell{11});  // re-target while navigating
  EXPECT_EQ(t.to, ProcessState::kNavigate);
  EXPECT_EQ(m.goal_cell(), 11u);
  t = m.handle(ev::Stop{});
  EXPECT_EQ(t.to, ProcessState::kLearn);
  EXPECT_TRUE(m.handle(ev::Stop{}).accepted);
  EXPECT_EQ(m.state(), ProcessState::kLearn);
  EXPECT_STREQ(to_string(ProcessState::kFindNode), "find_node");
  EXPECT_STREQ(to_string(FindNodePhase::kTurnNeck), "turn_neck");
}

}  // namespace
}  // namespace tessera
