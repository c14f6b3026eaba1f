// tessera: the command-line program. Every subcommand is thin glue over the library
// (cmd_<name>.cpp parses into an options struct, calls the library, writes through io).
#include <CLI/CLI.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "tessera/report/core_report.hpp"

int main(int argc, char** argv) {
  using namespace tessera::cli;
  CLI::App app{"tessera: 2D indoor mapping, exploration and SLAM for mobile robots"};
  // Every option bound to a variable records its default, which --print-config prints.
  app.option_defaults()->always_capture_default();
  app.set_version_flag("--version", tessera::tessera_version());
  app.require_subcommand(1);

  ExploreCommand explore(app);
  RenderCommand render(app);
  InfoCommand info(app);
  ConvertCommand convert(app);
  BobCommand bob(app);
  PosegraphCommand posegraph(app);
  EvalCommand eval(app);
  SlamCommand slam(app);
  FusionCommand fusion(app);
  SimCommand sim(app);
  PlayCommand play(app);
  TeamCommand team(app);
  SessionCommand session(app);
  LocalizeCommand localize(app);
  GridmatchCommand gridmatch(app);
  add_config_options(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  if (const int code = handle_config_options(app); code >= 0) return code;
  if (explore.parsed()) return explore.run();
  if (render.parsed()) return render.run();
  if (info.parsed()) return info.run();
  if (convert.parsed()) return convert.run();
  if (bob.parsed()) return bob.run();
  if (posegraph.parsed()) return posegraph.run();
  if (eval.parsed()) return eval.run();
  if (slam.parsed()) return slam.run();
  if (fusion.parsed()) return fusion.run();
  if (sim.parsed()) return sim.run();
  if (play.parsed()) return play.run();
  if (team.parsed()) return team.run();
  if (session.parsed()) return session.run();
  if (localize.parsed()) return localize.run();
  if (gridmatch.parsed()) return gridmatch.run();
  return kExitUsage;
}
