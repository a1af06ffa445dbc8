"""``ros2 lifecycle set NODE TRANSITION`` run by a launch file (ouster-ros'
sensor.composite.launch.xml: ``<executable cmd="$(find-exec ros2) lifecycle set
/$(var ouster_ns)/os_sensor configure"/>`` beside its lifecycle node os_driver, fixed
by 09c0233 to name /ouster/os_driver). Three things kept it from being seen: ros2 not on
the configuration's PATH made ``$(find-exec ros2)`` unknown, so the command was not
read; the verb was not modelled (ros2lifecycle calls NODE/get_available_transitions and
NODE/change_state); and client-without-server took every client of a lifecycle service
for the node's own, although no node of that name runs."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import UNDECIDED, load_catalogue, run_rule

(RULE,) = [r for r in load_catalogue() if r.id == "client-without-server"]

DRIVER = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp_lifecycle::LifecycleNode>("os_driver");
  rclcpp::spin(node->get_node_base_interface());
}
"""

LAUNCH = """<launch>
  <arg name="ouster_ns" default="ouster"/>
  <group>
    <push-ros-namespace namespace="$(var ouster_ns)"/>
    <node pkg="lidar" exec="os_driver" name="os_driver"/>
  </group>
  <executable cmd="$(find-exec ros2) lifecycle set /$(var ouster_ns)/{name} configure"
    launch-prefix="bash -c 'sleep 0; $0 $@'" output="screen"/>
</launch>
"""


def _findings(write_tree, name: str) -> tuple[list[str], list[str]]:
    root = write_tree({
        "src/lidar/package.xml": package_xml("lidar", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>rclcpp_lifecycle</depend>"
            "</package>"),
        "src/lidar/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(lidar)\n"
                                    "find_package(ament_cmake REQUIRED)\n"
                                    "add_executable(os_driver src/driver.cpp)\n"
                                    "install(TARGETS os_driver DESTINATION lib/${PROJECT_NAME})\n"
                                    "ament_package()\n",
        "src/lidar/src/driver.cpp": DRIVER,
        "src/lidar/launch/sensor.launch.xml": LAUNCH.replace("{name}", name),
        "project.yaml": "project: p\ndistro: jazzy\n"
                        "configurations:\n  c: [lidar/launch/sensor.launch.xml]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""}, Options(cache_dir=None))
    (config,) = model.configurations
    cli = [n for n in config.nodes if n.node is not None and n.node.package == "ros2lifecycle"]
    assert [sorted((c.kind, c.name) for c in n.node.calls) for n in cli] == [[
        ("client", f"/ouster/{name}/change_state"),
        ("client", f"/ouster/{name}/get_available_transitions")]]
    found = run_rule(RULE, model)
    return ([f.message for f in found if not f.rule.endswith(UNDECIDED)],
            [f.message for f in found if f.rule.endswith(UNDECIDED)])


def test_lifecycle_set_of_a_node_that_does_not_run_has_no_server(write_tree) -> None:
    warnings, undecided = _findings(write_tree, "os_sensor")
    assert sorted(m.split("'s client of ")[1].split(" ")[0] for m in warnings) == [
        "/ouster/os_sensor/change_state", "/ouster/os_sensor/get_available_transitions"]
    assert not undecided


def test_lifecycle_set_of_the_running_lifecycle_node_is_served(write_tree) -> None:
    warnings, undecided = _findings(write_tree, "os_driver")
    assert not warnings and not undecided
