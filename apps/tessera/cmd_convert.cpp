#include "commands.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/render/render.hpp"

namespace tessera::cli {

ConvertCommand::ConvertCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "convert",
      "Convert a map between formats: any readable map to ROS map_server (.yaml + .pgm) or .png");
  sub_->add_option("in", in_, "Input map file")->required();
  sub_->add_option("out", out_, "Output: a .yaml (writes the .pgm beside it) or a .png")
      ->required();
  sub_->add_option("--map-resolution-m", map_resolution_m_,
                   "Cell size for input files that carry none (images, Moving AI)");
}

int ConvertCommand::run() const {
  const std::string ext = out_.extension().string();
  if (ext != ".yaml" && ext != ".yml" && ext != ".png") {
    return report_error(usage_error(out_.string() + ": output must end in .yaml or .png"));
  }
  MapLoadOptions load_options;
  load_options.resolution_m = map_resolution_m_;
  Result<LoadedMap> loaded = load_map(in_, load_options);
  if (!loaded) return report_error(loaded.error());
  if (ext == ".png") {
    RenderLayers layers;
    layers.map = &loaded->map;
    if (Status s = write_png(out_, layers); !s) return report_error(s.error());
  } else if (Status s = write_map_yaml(loaded->map, out_, MapSaveOptions{}); !s) {
    return report_error(s.error());
  }
  return kExitOk;
}

}  // namespace tessera::cli
