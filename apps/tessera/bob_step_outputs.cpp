#include "bob_step_outputs.hpp"

#include <fmt/format.h>

#include <string>

#include "tessera/io/atomic_file.hpp"
#include "tessera/io/image_file.hpp"
#include "tessera/report/bob_monitor.hpp"

namespace tessera::cli {

BobStepOutputs::BobStepOutputs(std::optional<std::filesystem::path> monitor_dir, MessageSink* sink,
                               const GridGeometry& robot_grid)
    : monitor_dir_(std::move(monitor_dir)) {
  if (sink != nullptr) recorder_.emplace(*sink, robot_grid);
}

Status BobStepOutputs::prepare() const {
  return monitor_dir_ ? ensure_directory(*monitor_dir_) : Status(Ok{});
}

std::function<void(const BobResult&)> BobStepOutputs::on_step() {
  if (!monitor_dir_ && !recorder_) return {};
  return [this](const BobResult& so_far) { step(so_far); };
}

Status BobStepOutputs::finish(const BobResult& final_run) {
  if (status_ && recorder_) status_ = recorder_->finish(final_run);
  return status_;
}

void BobStepOutputs::step(const BobResult& so_far) {
  if (!status_) return;
  if (monitor_dir_) {
    Result<std::string> png = encode_png(render_bob_monitor(so_far));
    if (!png) {
      status_ = png.error();
      return;
    }
    status_ = write_file_atomic(*monitor_dir_ / fmt::format("step_{:05d}.png", frame_++), *png);
    if (!status_) return;
  }
  if (recorder_) status_ = recorder_->step(so_far);
}

}  // namespace tessera::cli
