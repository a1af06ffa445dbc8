"""The hash containers' own members in the std stand-ins: ``reserve``, ``rehash``,
``bucket_count``, ``load_factor`` / ``max_load_factor``, ``hash_function`` and
``key_eq`` of ``std::unordered_map`` and ``std::unordered_set``, which the ordered
containers they stand in as do not have. rm_engineer's arm_servo config loader calls
``joint_index.reserve(n)`` in the function that declares the node's parameters: a
parse error there made the node partial (CPP_NODE_PARTIAL) and hid those reads."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>
#include <rclcpp/rclcpp.hpp>

struct Config {
  std::vector<std::string> joint_names;
  std::unordered_map<std::string, std::size_t> joint_index;
  std::unordered_set<std::string> seen;
};

Config load(rclcpp::Node& node) {
  Config cfg;
  node.declare_parameter("joint_names", std::vector<std::string>{});
  cfg.joint_names = node.get_parameter("joint_names").as_string_array();
  cfg.joint_index.reserve(cfg.joint_names.size());
  cfg.seen.reserve(cfg.joint_names.size());
  cfg.joint_index.rehash(cfg.joint_index.bucket_count() * 2);
  cfg.joint_index.max_load_factor(0.5f);
  float load = cfg.joint_index.load_factor() + cfg.seen.max_load_factor();
  std::size_t h = cfg.joint_index.hash_function()("a") + cfg.seen.bucket_count();
  bool same = cfg.seen.key_eq()("a", "a");
  if (load >= 0 && same && h >= 0) {
    node.declare_parameter("rate", 10.0);
  }
  return cfg;
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("servo");
  Config cfg = load(*node);
  rclcpp::spin(node);
}
"""


def test_hash_containers_have_their_bucket_members(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "joint_names"), ("declare", "rate"), ("read", "joint_names")]
