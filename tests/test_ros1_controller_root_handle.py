"""ROS 1 ros_control calls a controller's ``init(hw, root_nh, controller_nh)`` with the
manager's own handle and ``<manager>/<controller>``. hector_quadrotor's controllers
subscribe to ``command/pose`` on the first: both handles were taken as the controller's,
``/controller/position/command/pose``, a topic nobody publishes (its pose_action
publishes ``command/pose``). And the calls of a controller loaded by a manager that
lives in another namespace than its host (Gazebo's ``/gazebo`` hosts ``/uav1``'s
manager) lost the manager's namespace: both quadrotors' controllers were one,
``/controller/...``. Now the root handle's names are the manager's, and the controller's
handle is ``<manager>/<controller>`` wherever its host is."""

from __future__ import annotations

import os
from typing import Any

from haros_arch.model.load import call_from_data
from haros_arch.model.serialise import to_data
from haros_arch.model.source import PrimitiveCall
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from tests.conftest import package_xml

CONTROLLER = """
    #include <ros/ros.h>
    #include <controller_interface/controller.h>
    #include <hardware_interface/joint_command_interface.h>
    #include <pluginlib/class_list_macros.h>
    #include <std_msgs/Float64.h>

    namespace quad {
    class PoseController
        : public controller_interface::Controller<hardware_interface::EffortJointInterface> {
     public:
      virtual bool init(hardware_interface::EffortJointInterface* hw, ros::NodeHandle& root_nh,
                        ros::NodeHandle& controller_nh) {
        root_nh.param<std::string>("world_frame", frame_, "world");
        sub_ = root_nh.subscribe("command/pose", 1, &PoseController::cb, this);
        controller_nh.param("gain", gain_, 1.0);
        pub_ = controller_nh.advertise<std_msgs::Float64>("state", 1);
        return true;
      }
      void update(const ros::Time&, const ros::Duration&) {}
     private:
      void cb(const std_msgs::Float64::ConstPtr&) {}
      ros::Subscriber sub_;
      ros::Publisher pub_;
      std::string frame_;
      double gain_;
    };
    // sawyer_sim_controllers' JointArrayController: an overload of three parameters
    // whose last is no handle; ``nh`` is the controller's own
    class ArrayController
        : public controller_interface::Controller<hardware_interface::EffortJointInterface> {
     public:
      virtual bool init(hardware_interface::EffortJointInterface* hw, ros::NodeHandle& nh) {
        return init(hw, nh, std::string(""));
      }
      bool init(hardware_interface::EffortJointInterface* hw, ros::NodeHandle& nh,
                const std::string& mode) {
        nh.param("joints", gain_, 1.0);
        return true;
      }
      void update(const ros::Time&, const ros::Duration&) {}
     private:
      double gain_;
    };
    }  // namespace quad
    PLUGINLIB_EXPORT_CLASS(quad::PoseController, controller_interface::ControllerBase)
    PLUGINLIB_EXPORT_CLASS(quad::ArrayController, controller_interface::ControllerBase)
    """

HARDWARE = """
    #include <ros/ros.h>
    #include <controller_manager/controller_manager.h>
    #include <hardware_interface/robot_hw.h>

    class Robot : public hardware_interface::RobotHW {
     public:
      void read() {}
      void write() {}
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "base_node");
      Robot robot;
      controller_manager::ControllerManager cm(&robot, ros::NodeHandle("uav1"));
      ros::spin();
      return 0;
    }
    """

LAUNCH = """<launch>
  <node name="base" pkg="quad" type="base_node"/>
  <group ns="uav1">
    <param name="pose/type" value="quad/PoseController"/>
    <node name="spawner" pkg="controller_manager" type="spawner" args="pose"/>
  </group>
  <group ns="uav2">
    <param name="pose/type" value="quad/PoseController"/>
    <param name="array/type" value="quad/ArrayController"/>
    <node name="spawner" pkg="controller_manager" type="spawner" args="pose array"/>
  </group>
</launch>
"""


def _config(write_tree: Any) -> Any:
    return _model(write_tree, LAUNCH).configurations[0]


def _model(write_tree: Any, launch: str) -> Any:
    xml = package_xml("quad", None).replace("</package>", "".join(
        f"<depend>{d}</depend>" for d in ("roscpp", "controller_manager", "controller_interface",
                                          "hardware_interface", "pluginlib", "std_msgs"))
        + '<export><controller_interface plugin="${prefix}/plugins.xml"/></export></package>')
    root = write_tree({
        "src/quad/package.xml": xml,
        "src/quad/CMakeLists.txt": (
            "project(quad)\nfind_package(catkin REQUIRED)\ncatkin_package()\n"
            "add_library(quad_controllers src/controller.cpp)\n"
            "add_executable(base_node src/base.cpp)\n"),
        "src/quad/plugins.xml": (
            '<library path="lib/libquad_controllers">'
            '<class name="quad/PoseController" type="quad::PoseController" '
            'base_class_type="controller_interface::ControllerBase"/>'
            '<class name="quad/ArrayController" type="quad::ArrayController" '
            'base_class_type="controller_interface::ControllerBase"/></library>'),
        "src/quad/src/controller.cpp": CONTROLLER,
        "src/quad/src/base.cpp": HARDWARE,
        "src/quad/launch/sim.launch": launch,
        "project.yaml": ("project: p\nworkspace: [src]\ndistro: noetic\nconfigurations:\n"
                         "  c: {launch: [quad/launch/sim.launch]}\n")})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return model


def test_the_type_of_a_controller_not_found_is_read_on_the_managers_handle(
        write_tree: Any) -> None:
    """UR's ROS 1 driver loads scaled_controllers, which are not in its workspace: the
    manager's read of ``<controller>/type`` was written with the global name
    (``/speed_scaling_state_controller/type``), a global-names info for a name the code
    never writes. It is the manager's handle's relative name, as for a class found."""
    from haros_arch.query import run_catalogue

    launch = LAUNCH.replace(
        '<node name="spawner" pkg="controller_manager" type="spawner" args="pose"/>',
        '<param name="missing/type" value="vendor_controllers/Missing"/>\n'
        '    <node name="spawner" pkg="controller_manager" type="spawner" '
        'args="pose missing"/>')
    model = _model(write_tree, launch)
    config = model.configurations[0]
    reads = [link for link in config.links if link.kind == "read"
             and link.node.name == "/base" and link.resource.name.endswith("/type")]
    assert sorted((link.resource.name, link.call.name) for link in reads) == [
        ("/uav1/missing/type", "uav1/missing/type"), ("/uav1/pose/type", "uav1/pose/type")]
    assert any(d.code == "PLUGIN_NOT_FOUND" for d in config.diagnostics)
    assert [f.message for f in run_catalogue(model) if f.rule == "global-names"] == []


def test_a_controllers_root_handle_is_its_managers_namespace(write_tree: Any) -> None:
    config = _config(write_tree)
    made = sorted((link.node.name, link.kind, link.resource.name) for link in config.links
                  if link.kind in ("subscribe", "publish", "read")
                  and link.node.name in ("/base", "/uav2/pose"))
    # uav1's manager lives in /base, in another namespace: the controller's handle is
    # /uav1/pose, its root handle /uav1
    assert ("/base", "subscribe", "/uav1/command/pose") in made
    assert ("/base", "read", "/uav1/world_frame") in made
    assert ("/base", "read", "/uav1/pose/gain") in made
    assert ("/base", "publish", "/uav1/pose/state") in made
    # uav2's manager is in no node of the configuration: the controller is an instance
    # of its own, /uav2/pose, whose root handle is /uav2
    assert ("/uav2/pose", "subscribe", "/uav2/command/pose") in made
    assert ("/uav2/pose", "read", "/uav2/world_frame") in made
    assert ("/uav2/pose", "read", "/uav2/pose/gain") in made
    assert not [name for _, _, name in made if "pose/command" in name]


def test_an_init_whose_third_parameter_is_no_handle_has_no_root_handle(
        write_tree: Any) -> None:
    """sawyer_simulator's controllers read ``joints`` in ``init(hw, nh, ctrl_type)``: the
    read was taken for the root handle's, ``/robot/joints``, and the controller's own
    ``joints`` left unread (a false parameter-set-not-read per joint)."""
    config = _config(write_tree)
    reads = {link.resource.name for link in config.links
             if link.kind == "read" and link.node.name == "/uav2/array"}
    assert "/uav2/array/joints" in reads and "/uav2/joints" not in reads


def test_the_root_handle_mark_is_kept_in_saved_models() -> None:
    call = PrimitiveCall("subscribe", "command/pose", "geometry_msgs/PoseStamped",
                         root_handle=True)
    assert call_from_data(to_data(call)).root_handle
    assert "root_handle" not in to_data(PrimitiveCall("subscribe", "x"))
