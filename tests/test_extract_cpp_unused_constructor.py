"""A free function that a file calls only from one constructor, with that constructor's
handle, makes its calls only where the constructor runs. voxblox's ``TsdfServer(nh,
nh_private)`` passes its private handle to ``getMeshIntegratorConfigFromRosParam``
(ros_params.h); esdf_server builds its TsdfServer by the constructor that takes the
configurations, so that short constructor never runs there, and its copy of the reads
was a second ``?/mesh_min_weight`` beside the right ``~mesh_min_weight``."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "unused_constructor")
SRC = os.path.join(ROOT, "src", "mapper", "src")


def _reads(*sources: str) -> list[tuple[str, str]]:
    found = extract_cpp([os.path.join(SRC, s) for s in sources], scan([ROOT]),
                        cache_dir=None)
    return sorted((c.kind, c.name) for c in found.calls)


def test_a_constructor_the_node_never_runs_passes_no_handle() -> None:
    # DistanceServer delegates to its long constructor, which builds the MapServer by
    # its long one: MapServer's short constructor, and the reads it passes its handle
    # to, never run
    assert _reads("distance_server_node.cpp", "map_server.cpp", "distance_server.cpp") == [
        ("read", "~mesh_min_weight"), ("read", "~resolution")]


def test_the_constructor_a_node_runs_still_passes_its_handle() -> None:
    # map_server builds MapServer by the short constructor: its reads on "mapping"; the
    # DistanceServer it never builds reads nothing
    assert _reads("map_server_node.cpp", "map_server.cpp", "distance_server.cpp") == [
        ("read", "mapping/mesh_min_weight"), ("read", "mapping/resolution")]


MANIFEST = """<package format="3"><name>planners</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>MIT</license>
<depend>rclcpp</depend><depend>geometry_msgs</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

PLANNER = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>

class BasePlanner {
public:
  virtual ~BasePlanner() = default;
  virtual void initialize(const rclcpp::Node::SharedPtr & node, const std::string & name) = 0;
};

class Planner : public BasePlanner {
public:
  Planner() = default;
  Planner(const rclcpp::Node::SharedPtr & node, const std::string & name) {
    initialize(node, name);
  }
  void initialize(const rclcpp::Node::SharedPtr & node, const std::string & name) override {
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(
      name + "/cmd", 10, [](const geometry_msgs::msg::Twist::SharedPtr) {});
  }
private:
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};

std::unique_ptr<BasePlanner> make() { return std::make_unique<Planner>(); }
"""

HOST = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>

class BasePlanner {
public:
  virtual ~BasePlanner() = default;
  virtual void initialize(const rclcpp::Node::SharedPtr & node, const std::string & name) = 0;
};
std::unique_ptr<BasePlanner> make();

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("host");
  std::unique_ptr<BasePlanner> planner = make();
  planner->initialize(node, "local");
  rclcpp::spin(node);
}
"""


def test_a_virtual_method_the_unused_constructor_calls_keeps_its_call(tmp_path) -> None:
    # the named constructor never runs (make() builds a Planner by the default one), but
    # the host calls ``initialize`` through the base: its subscription stays
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "planner.cpp").write_text(PLANNER)
    (tmp_path / "main.cpp").write_text(HOST)
    found = extract_cpp([str(tmp_path / "main.cpp"), str(tmp_path / "planner.cpp")],
                        scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name.rsplit("/", 1)[-1]) for c in found.calls] == [("subscribe", "cmd")]
