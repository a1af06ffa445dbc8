"""The std stand-ins have the rest of ``<cstring>`` in ``std`` (cartographer_ros'
ros_log_sink.cc and yasmin's logs.hpp: ``std::strrchr(path, '/')``) and ``std::list``'s
own operations (``splice``: yasmin's demangle cache, autoware_utils' lru_cache, MoveIt's
time-optimal trajectory generation; ``remove_if``, ``unique``, ``merge``, ``reverse``,
``emplace_front``, ``sort(comp)``). Each was a parse error beside the node's calls."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <cstring>
#include <list>
#include <string>
#include <unordered_map>

struct Lru {
  std::list<std::string> order;
  std::unordered_map<std::string, std::list<std::string>::iterator> where;
  void touch(const std::string& key) {
    auto it = where.find(key);
    order.splice(order.begin(), order, it->second);
    std::list<std::string> other;
    order.splice(order.end(), other);
    order.splice(order.end(), std::move(other), other.begin(), other.end());
    order.remove_if([](const std::string& s) { return s.empty(); });
    order.unique();
    order.merge(other, [](const std::string& a, const std::string& b) { return a < b; });
    order.reverse();
    order.emplace_front("first");
    order.sort([](const std::string& a, const std::string& b) { return a > b; });
  }
};

const char* base_name(const char* path) {
  const char* base = std::strrchr(path, '/');
  const char* found = std::strstr(path, "ros");
  const void* byte = std::memchr(path, 0, 4);
  std::size_t span = std::strspn(path, "/") + std::strcspn(path, ".");
  return base != nullptr && found && byte && span ? base + 1 : std::strchr(path, '/');
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>(base_name(argv[0]) ? "n" : "m");
  auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  return 0;
}
"""


def test_cstring_and_list_operations_parse(tmp_path) -> None:
    source = tmp_path / "lru.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
