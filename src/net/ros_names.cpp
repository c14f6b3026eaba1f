// ROS 2 topic and type names and their DDS spellings (ros_names.hpp; ROS 2 design article
// "Topic and Service name mapping to DDS", rmw_cyclonedds_cpp's create_topic_name).
#include "tessera/net/ros_names.hpp"

namespace tessera::net {
namespace {

bool is_token_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace

Status check_topic_name(std::string_view name) {
  const std::string quoted = "topic name '" + std::string(name) + "'";
  if (name.empty() || name.front() != '/') return input_error(quoted + " must start with '/'");
  if (name.size() == 1) return input_error(quoted + " names no topic");
  if (name.back() == '/') return input_error(quoted + " must not end with '/'");
  bool token_start = true;
  for (std::size_t i = 1; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '/') {
      if (token_start) return input_error(quoted + " has an empty token ('//')");
      token_start = true;
      continue;
    }
    if (!is_token_char(c)) {
      return input_error(quoted + " has '" + std::string(1, c) +
                         "'; tokens use letters, digits and '_'");
    }
    if (token_start && c >= '0' && c <= '9') {
      return input_error(quoted + " has a token starting with a digit");
    }
    token_start = false;
  }
  return Ok{};
}

Result<std::string> resolve_topic_name(std::string_view name, std::string_view ns) {
  std::string full;
  if (!name.empty() && name.front() == '/') {
    full = name;
  } else {
    full = ns;
    if (full.empty() || full.back() != '/') full += '/';
    full += name;
  }
  if (Status ok = check_topic_name(full); !ok.ok()) return ok.error();
  return full;
}

std::string dds_topic_name(std::string_view ros_topic) { return "rt" + std::string(ros_topic); }

Result<std::string> dds_type_name(std::string_view ros_type) {
  const std::size_t msg = ros_type.find("/msg/");
  if (msg == std::string_view::npos || msg == 0 || msg + 5 >= ros_type.size() ||
      ros_type.find('/', msg + 5) != std::string_view::npos) {
    return input_error("type name '" + std::string(ros_type) + "' is not <package>/msg/<Type>");
  }
  return std::string(ros_type.substr(0, msg)) +
         "::msg::dds_::" + std::string(ros_type.substr(msg + 5)) + "_";
}

}  // namespace tessera::net
