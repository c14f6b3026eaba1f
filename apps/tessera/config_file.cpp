#include "config_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <optional>
#include <vector>

#include "cli_support.hpp"

namespace tessera::cli {
namespace {

constexpr const char* kConfigOption = "--config";
constexpr const char* kPrintConfigOption = "--print-config";

/// "--lidar-range-m" -> "lidar_range_m"; empty for an option with no long name (a positional).
std::string key_of(const CLI::Option& option) {
  const std::vector<std::string>& names = option.get_lnames();
  if (names.empty()) return {};
  std::string key = names.front();
  for (char& c : key) {
    if (c == '-') c = '_';
  }
  return key;
}

/// A setting: a named option that is neither help, nor --config itself, nor an input.
bool is_setting(const CLI::Option& option) {
  if (option.get_lnames().empty() || option.get_required()) return false;
  const std::string name = option.get_name();
  return name != "--help" && name != kConfigOption && name != kPrintConfigOption &&
         name != "--version";
}

/// 1-based line of a YAML node (yaml-cpp counts from 0).
int line_of(const YAML::Node& node) { return node.Mark().line + 1; }

std::string where(const std::filesystem::path& file, int line) {
  return fmt::format("{}:{}", file.string(), line);
}

bool takes_many(const CLI::Option& option) { return option.get_items_expected_max() > 1; }

/// --quiet and the like: no value on the command line, true or false in a file.
bool is_flag(const CLI::Option& option) { return option.get_type_size() == 0; }

}  // namespace

void add_config_options(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (!sub->get_subcommands([](CLI::App*) { return true; }).empty()) {
      add_config_options(*sub);
      continue;
    }
    sub->add_option(std::string(kConfigOption),
                    "Read settings from this YAML file (keys: the options below without their "
                    "dashes, '-' as '_'); the command line overrides it")
        ->check(CLI::ExistingFile);
    sub->add_flag(kPrintConfigOption)
        ->description("Print the effective settings as YAML that --config reads back, and stop");
  }
}

CLI::App& parsed_leaf(CLI::App& app) {
  CLI::App* leaf = &app;
  for (;;) {
    std::vector<CLI::App*> parsed = leaf->get_subcommands();
    if (parsed.empty()) return *leaf;
    leaf = parsed.front();
  }
}

Status apply_config_file(CLI::App& command, const std::filesystem::path& file) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    return usage_error(file.string() + ": cannot read the configuration file");
  } catch (const YAML::Exception& e) {
    return usage_error(where(file, e.mark.line + 1) + ": not YAML: " + e.msg);
  }
  if (root.IsNull()) return Ok{};  // an empty file sets nothing
  if (!root.IsMap()) {
    return usage_error(where(file, line_of(root)) +
                       ": expected a map of settings (key: value), one per line");
  }
  std::vector<std::string> known;
  for (const CLI::Option* option : command.get_options()) {
    if (is_setting(*option)) known.push_back(key_of(*option));
  }
  for (const auto& entry : root) {
    const int line = line_of(entry.first);
    if (!entry.first.IsScalar()) {
      return usage_error(where(file, line) + ": a key must be a plain name");
    }
    const std::string key = entry.first.Scalar();
    CLI::Option* option = nullptr;
    for (CLI::Option* candidate : command.get_options()) {
      if (key_of(*candidate) == key) option = candidate;
    }
    if (option == nullptr || !is_setting(*option)) {
      const std::string why = option != nullptr ? " (an input: give it on the command line)"
                                                : fmt::format(" (expected one of: {})",
                                                              fmt::join(known, ", "));
      return usage_error(where(file, line) + ": unknown key '" + key + "'" + why);
    }
    const std::string in_key = where(file, line_of(entry.second)) + ": key '" + key + "': ";
    std::vector<std::string> values;
    if (entry.second.IsScalar()) {
      values.push_back(entry.second.Scalar());
    } else if (entry.second.IsSequence() && takes_many(*option)) {
      for (const YAML::Node& item : entry.second) {
        if (!item.IsScalar()) return usage_error(in_key + "expected a list of plain values");
        values.push_back(item.Scalar());
      }
    } else if (entry.second.IsNull()) {
      return usage_error(in_key + "no value (leave the key out for the default)");
    } else {
      return usage_error(in_key + (takes_many(*option) ? "expected a value or a list of values"
                                                       : "expected one plain value"));
    }
    if (option->count() > 0) continue;  // the command line wins
    try {
      for (const std::string& v : values) option->add_result(v);
      option->run_callback();
    } catch (const CLI::Error& e) {
      return usage_error(in_key + e.what());
    }
  }
  return Ok{};
}

std::string effective_config_yaml(const CLI::App& command) {
  std::string yaml = fmt::format("# tessera {}: effective settings (read back with --config)\n",
                                 command.get_display_name(true));
  for (const CLI::Option* option : command.get_options()) {
    if (!is_setting(*option)) continue;
    const std::string key = key_of(*option);
    std::vector<std::string> values;
    if (option->count() > 0) {
      values = option->results();
    } else if (const std::string d = option->get_default_str(); !d.empty() && d != "[]") {
      values.push_back(d);
    } else if (is_flag(*option)) {
      values.push_back("false");  // a flag not given
    }
    YAML::Emitter out;
    out << YAML::BeginMap << YAML::Key << key << YAML::Value;
    if (takes_many(*option)) {
      out << YAML::Flow << YAML::BeginSeq;
      for (const std::string& v : values) out << v;
      out << YAML::EndSeq;
    } else if (!values.empty()) {
      out << values.back();
    } else {
      out << YAML::Null;
    }
    out << YAML::EndMap;
    // A list given no values is unset too: an empty list does not read back (CLI11 wants one).
    const bool unset = values.empty();
    yaml += (unset ? "# " : "") + std::string(out.c_str()) + (unset ? "  (unset)" : "") + "\n";
  }
  return yaml;
}

int handle_config_options(CLI::App& app) {
  CLI::App& command = parsed_leaf(app);
  const CLI::Option* config = command.get_option_no_throw(kConfigOption);
  if (config != nullptr && config->count() > 0) {
    if (Status s = apply_config_file(command, config->as<std::string>()); !s) {
      return report_error(s.error());
    }
  }
  const CLI::Option* print = command.get_option_no_throw(kPrintConfigOption);
  if (print != nullptr && print->count() > 0) {
    fmt::print("{}", effective_config_yaml(command));
    return kExitOk;
  }
  return -1;
}

}  // namespace tessera::cli
