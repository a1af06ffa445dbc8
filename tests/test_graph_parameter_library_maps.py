"""generate_parameter_library's ``__map_<list>`` parameters (joint_trajectory_controller's
``gains.__map_joints.p``): the listener declares one per element of the list parameter
in the configuration, so a node launched with ``joints: [a, b]`` declares ``gains.a.p``
and ``gains.b.p``, one launched without it the elements of the YAML's default, and one
whose list is set to a value not known keeps ``gains.?.p`` (undecided). The extractor
named them from the default only, whatever the launch file gave."""

from __future__ import annotations

import os
import shutil

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "parameter_library", "src",
                       "joint_gain_controller")

STANDALONE = """#include <memory>
#include <rclcpp/rclcpp.hpp>
#include "joint_gain_controller/joint_gain_controller_parameters.hpp"
class Standalone : public rclcpp::Node {
 public:
  Standalone() : rclcpp::Node("standalone") {
    listener_ = std::make_shared<::joint_gain_controller::ParamListener>(
      this->get_node_parameters_interface());
  }
 private:
  std::shared_ptr<::joint_gain_controller::ParamListener> listener_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Standalone>());
  return 0;
}
"""

LAUNCH = """<launch>
  <arg name="joints"/>
  <node pkg="joint_gain_controller" exec="standalone" name="given">
    <param name="joints" value="[wrist, finger]"/>
    <param name="command_joints" value="[wrist]"/>
  </node>
  <node pkg="joint_gain_controller" exec="standalone" name="defaults"/>
  <node pkg="joint_gain_controller" exec="standalone" name="unknown">
    <param name="joints" value="$(var joints)"/>
  </node>
</launch>
"""


def test_a_map_declares_one_parameter_per_element_of_its_list(tmp_path) -> None:
    package = tmp_path / "src" / "joint_gain_controller"
    shutil.copytree(PACKAGE, package)
    (package / "src" / "standalone.cpp").write_text(STANDALONE)
    (package / "launch").mkdir()
    (package / "launch" / "gains.launch.xml").write_text(LAUNCH)
    with open(package / "CMakeLists.txt", encoding="utf-8") as handle:
        cmake = handle.read().replace("ament_package()", (
            "add_executable(standalone src/standalone.cpp)\n"
            "target_link_libraries(standalone joint_gain_controller_parameters)\n"
            "install(TARGETS standalone DESTINATION lib/${PROJECT_NAME})\n"
            "ament_package()"))
    (package / "CMakeLists.txt").write_text(cmake)
    (tmp_path / "project.yaml").write_text(
        "project: p\nworkspace: src\nconfigurations:\n  c:\n"
        "    launch: [joint_gain_controller/launch/gains.launch.xml]\n")
    model = analyse(load(str(tmp_path / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    declared = {n.name: sorted(link.name for link in n.reads + n.writes
                               if "gains." in link.name or "feedforward." in link.name)
                for n in config.nodes}
    assert declared == {
        "/given": ["/given/feedforward.wrist.scale", "/given/gains.finger.i",
                   "/given/gains.finger.p", "/given/gains.wrist.i", "/given/gains.wrist.p"],
        # the YAML's defaults: joints [shoulder, elbow], command_joints [] (none)
        "/defaults": ["/defaults/gains.elbow.i", "/defaults/gains.elbow.p",
                      "/defaults/gains.shoulder.i", "/defaults/gains.shoulder.p"],
        "/unknown": ["/unknown/gains.?.i", "/unknown/gains.?.p"],
    }
