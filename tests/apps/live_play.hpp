#pragma once
// A live node (`tessera slam --ros`, `tessera localize --ros`) fed by `tessera play`: two
// processes on this test's DDS domain, as a robot's driver and its node run.
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "cli_run.hpp"
#include "support/dds_isolation.hpp"
#include "support/temp_dir.hpp"

namespace tessera::support {

struct LivePlay {
  CliRun play;
  nlohmann::json report;  // the node's report.json; null when it wrote none
  std::string node_said;  // the node's output when it wrote no report
};

/// Runs `tessera <node_args>` in the background, writing to dir/node, and `tessera play
/// <play_args>` into it. The node finishes 3 s after the last scan (at most 300 s: if the player
/// fails, no scan comes and nothing else would stop it).
inline LivePlay play_into_node(const TempDir& dir, const std::string& node_args,
                               const std::string& play_args) {
  const std::string domain = std::to_string(test_dds_domain());
  const std::string node_cmd = "timeout 300 " + std::string(TESSERA_CLI) + " " + node_args +
                               " --quiet --domain " + domain + " --idle-exit-s 3 --out " +
                               (dir.path() / "node").string() + " > " +
                               (dir.path() / "node.txt").string() + " 2>&1";
  std::thread node([&] { std::system(node_cmd.c_str()); });
  LivePlay run;
  run.play = run_cli("play " + play_args + " --domain " + domain + " --wait-s 60");
  node.join();
  std::ifstream in(dir.path() / "node" / "report.json");
  if (in) {
    run.report = nlohmann::json::parse(in);
  } else {
    std::ostringstream said;
    said << std::ifstream(dir.path() / "node.txt").rdbuf();
    run.node_said = said.str();
  }
  return run;
}

}  // namespace tessera::support
