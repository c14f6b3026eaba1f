#pragma once
// Heading reversals: how often a robot swings its heading back, the figure the zigzag of the Fusion
// SLAM thesis (sections 5.2.1 and 6.1) is measured by (docs/fusion-navigation.md). A reversal is
// the heading turning back by more than threshold_rad from its last extreme; the hysteresis keeps
// jitter below the threshold from counting, and a steady turn (a bend, a U-turn) counts nothing.
namespace tessera {

class HeadingReversalCounter {
 public:
  /// Precondition: threshold_rad > 0 and finite.
  explicit HeadingReversalCounter(double threshold_rad = 0.1);

  /// The next heading sample (any range; steps between samples are taken as the shorter way
  /// round, so samples must come faster than a half turn).
  void add(double heading_rad);

  [[nodiscard]] int reversals() const { return reversals_; }

 private:
  double threshold_rad_;
  bool started_ = false;
  double last_rad_ = 0.0;
  double unwrapped_rad_ = 0.0;
  double extreme_rad_ = 0.0;
  int direction_ = 0;  // +1 turning left, -1 turning right, 0 not yet beyond the threshold
  int reversals_ = 0;
};

}  // namespace tessera
