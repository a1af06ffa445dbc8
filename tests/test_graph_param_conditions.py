"""Source conditions over a member that holds a parameter, or over main's argc / argv,
are decided per node instance: false drops the link (a CONDITION_FALSE info says so),
true makes it unconditional, anything else stays a condition."""

from __future__ import annotations

import json
import os

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.model.conditions import Condition
from haros_arch.models.format import from_document
from haros_arch.pipeline import Options, analyse
from haros_arch.project import load
from haros_arch.query.catalogue import run_catalogue
from haros_arch.workspace import scan

NODE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <string>

    class Gated {
     public:
      Gated() : verbose_(false), publish_debug_(true) {}
      void init() {
        ros::NodeHandle nh, pnh("~");
        pnh.param("publish_debug", publish_debug_, false);
        pnh.param("publish_status", publish_status_, true);
        pnh.param("verbose", verbose_, verbose_);
        pnh.param("twice", twice_, false);
        pnh.getParam("twice_again", twice_);
        pnh.param("mode", mode_, 1);
        pnh.param("from_launch", from_launch_, false);
        if (publish_debug_) debug_ = nh.advertise<std_msgs::String>("debug", 1);
        if (publish_status_) {
          status_ = nh.advertise<std_msgs::String>("status", 1);
        } else {
          quiet_ = nh.advertise<std_msgs::String>("quiet", 1);
        }
        if (verbose_) chatty_ = nh.advertise<std_msgs::String>("chatty", 1);
        if (twice_) twice_pub_ = nh.advertise<std_msgs::String>("twice", 1);
        if (mode_ == 2) two_ = nh.advertise<std_msgs::String>("mode_two", 1);
        if (this->from_launch_) launched_ = nh.advertise<std_msgs::String>("launched", 1);
        if (unread_) unread_pub_ = nh.advertise<std_msgs::String>("unread", 1);
        if (!from_launch_ && unread_) both_ = nh.advertise<std_msgs::String>("both", 1);
      }
      void reset() {
        ros::NodeHandle pnh("~");
        pnh.param("publish_debug", publish_debug_, false);
      }
     private:
      bool verbose_, publish_debug_, publish_status_, twice_, from_launch_;
      bool unread_ = false;
      int mode_;
      ros::Publisher debug_, status_, quiet_, chatty_, twice_pub_, two_, launched_;
      ros::Publisher unread_pub_, both_;
    };

    template <typename T>
    class Filter {
     public:
      void load() { ros::NodeHandle p("~"); p.param("publish_accel", accel_, false); }
      void start() {
        ros::NodeHandle nh;
        if (accel_) pub_ = nh.advertise<std_msgs::String>("accel", 1);
      }
      bool ready(T x) { return accel_ && x.ok(); }  // reads accel_: not a write
      bool accel_;
      ros::Publisher pub_;
    };

    struct Ok { bool ok() const { return true; } };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "gated");
      Gated gated;
      gated.init();
      auto on_reset = &Gated::reset;  // (a callback: what reset() reads may be read)
      (void)on_reset;
      Filter<Ok> filter;
      filter.load();
      filter.start();
      ros::NodeHandle nh;
      ros::Publisher replay;
      if ((argc >= 2) && (std::string(argv[1]) == "--replay")) {
        replay = nh.advertise<std_msgs::String>("replay", 1);
      }
      ros::spin();
    }
    """

LAUNCH = """
    <launch>
      <node pkg="gated" type="gated" name="gated">
        <param name="from_launch" value="true"/>
        <param name="publish_status" value="false"/>
      </node>
      <node pkg="gated" type="gated" name="replayer" args="--replay">
        <remap from="debug" to="replayer_debug"/>
      </node>
      <arg name="unset"/>
      <node pkg="gated" type="gated" name="unknown_args" args="$(arg unset)"/>
    </launch>
    """


def _workspace(write_tree):
    return write_tree({
        "src/gated/package.xml": package_xml("gated"),
        "src/gated/CMakeLists.txt": "project(gated)\nadd_executable(gated src/gated.cpp)\n",
        "src/gated/src/gated.cpp": NODE,
        "src/gated/launch/gated.launch": LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [gated/launch/gated.launch]\n",
    })


def _config(root):
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    return model.configuration("c")


def _publishers(config, node: str) -> dict[str, list[str]]:
    return {link.rosname.own: [c.text for c in link.conditions] for link in config.links
            if link.node.name == node and link.kind == "publish"}


def test_the_extractor_names_the_member_a_read_stores_into(write_tree):
    root = _workspace(write_tree)
    result = extract_cpp([str(root / "src/gated/src/gated.cpp")], scan([str(root)]),
                         cache_dir=None)
    stored = {c.name: c.variable for c in result.calls if c.kind == "read"}
    assert stored == {"~publish_debug": "publish_debug_", "~publish_status": "publish_status_",
                      "~verbose": "verbose_", "~twice": None, "~twice_again": None,
                      "~mode": "mode_", "~from_launch": "from_launch_",
                      "~publish_accel": "accel_"}
    # read twice into the member, the same parameter with the same default: each
    # write of the member is that parameter (a read of another one into the same
    # member, ``twice_``, is not)
    assert [c.variable for c in result.calls if c.name == "~publish_debug"] == [
        "publish_debug_", "publish_debug_"]
    defaults = {c.name: c.default for c in result.calls if c.kind == "read"}
    assert defaults["~verbose"] is False  # the constructor's value of the member
    replay = next(c for c in result.calls if c.name == "replay")
    assert [c.program_args for c in replay.conditions] == [True]
    debug = next(c for c in result.calls if c.name == "debug")
    assert [c.program_args for c in debug.conditions] == [False]


def test_conditions_decided_by_parameters_and_arguments(write_tree):
    config = _config(_workspace(write_tree))
    gated = _publishers(config, "/gated")
    for absent in ("debug", "status", "chatty", "mode_two", "replay", "both", "accel"):
        assert absent not in gated
    assert gated["quiet"] == [] and gated["launched"] == []
    assert gated["twice"] == ["twice_"] and gated["unread"] == ["unread_"]
    replayer = _publishers(config, "/replayer")
    assert replayer["replay"] == []  # args="--replay"
    assert "status" in replayer and "quiet" not in replayer  # publish_status defaults true
    assert "replayer_debug" not in replayer  # a dropped link leaves no topic behind
    assert config.topic("/replayer_debug") is None
    unknown = _publishers(config, "/unknown_args")
    assert unknown["replay"] == ["(argc >= 2) && (std::string(argv[1]) == \"--replay\")"]
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    assert any("/gated: no publish /debug" in m and "publish_debug_" in m for m in said)
    assert any("/gated: no publish /replay" in m for m in said)


def test_interface_models_carry_the_member_and_program_args():
    """A model file's read names its member and a condition says it is main's: the
    graph decides them for a node taken from the model as for one from source."""
    data = {"schema": "haros-arch-model/2", "package": "gated", "distro": "noetic",
            "version": "1", "nodes": [{"name": "gated/gated", "calls": [
                {"kind": "read", "name": "~publish_debug", "type": "bool",
                 "has_default": True, "default": False, "variable": "publish_debug_",
                 "location": {"package": "gated", "file": "src/g.cpp", "line": 3}},
                {"kind": "publish", "name": "debug", "type": "std_msgs/String",
                 "conditions": [{"text": "publish_debug_", "statement": "if",
                                 "location": {"package": "gated", "file": "src/g.cpp",
                                              "line": 4}}]},
                {"kind": "publish", "name": "replay", "type": "std_msgs/String",
                 "conditions": [{"text": "argc > 1", "statement": "if",
                                 "program_args": True}]}]}]}
    node = from_document(json.loads(json.dumps(data))).nodes[0]
    assert node.calls[0].variable == "publish_debug_"
    assert node.calls[2].conditions == (Condition("argc > 1", program_args=True),)


NODE2 = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Gated : public rclcpp::Node {
     public:
      Gated() : Node("gated2") {
        debug_ = declare_parameter("publish_debug", false);
        status_ = this->declare_parameter("publish_status", false);
        if (debug_) {
          debug_pub_ = create_publisher<std_msgs::msg::String>("debug", 10);
        }
        if (status_) {
          status_pub_ = create_publisher<std_msgs::msg::String>("status", 10);
        }
        declare_parameter("publish_extra", true);
        get_parameter("publish_extra", extra_);
        if (extra_) {
          extra_pub_ = create_publisher<std_msgs::msg::String>("extra", 10);
        }
      }
     private:
      bool debug_, status_, extra_;
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr debug_pub_, status_pub_, extra_pub_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Gated>());
    }
    """

LAUNCH2 = """
    <launch>
      <node pkg="gated2" exec="gated2" name="gated2">
        <param name="publish_status" value="true"/>
      </node>
    </launch>
    """


def test_ros2_declared_parameters_decide_conditions(write_tree):
    root = write_tree({
        "src/gated2/package.xml": package_xml("gated2", build_type="ament_cmake"),
        "src/gated2/CMakeLists.txt": "project(gated2)\nadd_executable(gated2 src/gated2.cpp)\n"
                                     "install(TARGETS gated2 DESTINATION lib/${PROJECT_NAME})\n",
        "src/gated2/src/gated2.cpp": NODE2,
        "src/gated2/launch/gated2.launch.xml": LAUNCH2,
        "project.yaml": "project: p\nconfigurations:\n  c: [gated2/launch/gated2.launch.xml]\n",
    })
    config = _config(root)
    published = _publishers(config, "/gated2")
    assert published.get("status") == []  # declared false, the launch file sets true
    assert "debug" not in published       # declared with the default false, not set
    # read without a default after a declaration with one: the declaration's default
    assert published.get("extra") == []


NODE3 = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>

    class Loader : public rclcpp::Node {
     public:
      Loader() : Node("loader") {
        declare_parameter("enable_selected_map_loading", false);
        declare_parameter("publish_partial_map", true);
        declare_parameter("debug_topics", false);
        if (get_parameter("enable_selected_map_loading").as_bool()) {
          selected_pub_ = create_publisher<std_msgs::msg::String>("selected", 10);
        }
        if (!this->get_parameter("publish_partial_map").as_bool()) {
          whole_pub_ = create_publisher<std_msgs::msg::String>("whole", 10);
        }
        if (get_parameter("debug_topics").as_bool()) {
          debug_pub_ = create_publisher<std_msgs::msg::String>("debug", 10);
        }
      }
     private:
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr selected_pub_, whole_pub_, debug_pub_;
    };

    int main(int argc, char** argv) {
      rclcpp::init(argc, argv);
      rclcpp::spin(std::make_shared<Loader>());
    }
    """


def test_ros2_get_parameter_values_decide_conditions(write_tree):
    # Autoware's lanelet2_map_loader_node.cpp:98: ``if (get_parameter(
    # "enable_selected_map_loading").as_bool())``: the node's parameter, as the launch file
    # sets it, else as the code declares it
    root = write_tree({
        "src/loader/package.xml": package_xml("loader", build_type="ament_cmake"),
        "src/loader/CMakeLists.txt": "project(loader)\nadd_executable(loader src/loader.cpp)\n"
                                     "install(TARGETS loader DESTINATION lib/${PROJECT_NAME})\n",
        "src/loader/src/loader.cpp": NODE3,
        "src/loader/launch/loader.launch.xml": """
            <launch>
              <node pkg="loader" exec="loader" name="loader">
                <param name="enable_selected_map_loading" value="true"/>
              </node>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [loader/launch/loader.launch.xml]\n",
    })
    published = _publishers(_config(root), "/loader")
    assert published == {"selected": []}  # set true; declared true (so not whole); false


def test_the_condition_grammar_reads_only_what_it_can_compute():
    from haros_arch.graph.conditions import decide, python_of
    from haros_arch.model.values import Unknown

    assert python_of("!a == b") == ("((not a) == b)", frozenset({"a", "b"}))
    assert python_of("this->x_ && _y") == ("(x_ and _y)", frozenset({"x_", "_y"}))
    assert python_of("x.size() > 0") == ("(len(x) > 0)", frozenset({"x"}))
    assert python_of('!args.empty() && args.at(1) == "bytes"') == (
        '((not (len(args) == 0)) and (args[1] == "bytes"))', frozenset({"args"}))
    assert python_of('get_parameter("a.b").as_bool()') == (
        "haros_parameter_612e62", frozenset({"haros_parameter_612e62"}))
    for text in ("get_parameter(name).as_bool()", 'get_parameter("a").as_array()',
                 'get_parameter("a")', "f(x)", "ns::flag", "x.begin() != x.end()",
                 "x.at(i) == 1", "x.size",
                 "int i = 0; i < n; ++i", "a = 1",
                 "__import__", "(" * 500 + "a" + ")" * 500, "a" * 2000, "default"):
        assert python_of(text) is None, text
    values = {"a": True, "b": 2}.get

    def known(name):
        found = values(name)
        return Unknown(name) if found is None else found
    assert decide(Condition("a && b == 2"), known) is True
    assert decide(Condition("a && b == 2", statement="else"), known) is False
    assert decide(Condition("a && c"), known) is None      # c has no value
    assert decide(Condition("!a && c"), known) is False    # decided whatever c is
    assert decide(Condition("a", statement="for"), known) is None
    assert decide(Condition("argc > 1"), known, [(["x", "y"], ["x"])]) is None  # not main's
    # main's local that keeps what rclcpp leaves (the program's name first); argv
    # itself is not known for a ROS 2 instance
    left = Condition('args.size() >= 3 && args.at(1) == "bytes"', program_args=True,
                     args_left="args")
    assert decide(left, known, [(None, ["throttle", "bytes", "/in"])]) is True
    assert decide(left, known, [(None, ["throttle", "messages", "/in"])]) is False
    assert decide(left, known, [(None, ["throttle", "bytes"])]) is False
    assert decide(left, known, None) is None  # the launch file's arguments not known
    assert decide(Condition("argc > 2", program_args=True, args_left="args"), known,
                  [(None, ["throttle", "bytes", "/in"])]) is None


def test_a_member_a_base_class_header_reads_decides_a_condition_in_another_file(
        write_tree):
    # pcl_ros: PCLNodelet::onInit (pcl_nodelet.h:212) reads ~use_indices into
    # use_indices_, which its constructor sets false; filter.cpp:113 subscribes ~indices
    # only if (use_indices_)
    root = write_tree({
        "src/lazy/package.xml": package_xml("lazy"),
        "src/lazy/CMakeLists.txt": "project(lazy)\nadd_executable(lazy src/lazy.cpp)\n",
        "src/lazy/include/lazy/base.h": """
            #include <ros/ros.h>
            class Base {
             public:
              Base() : use_indices_(false) {}
              void init() {
                ros::NodeHandle pnh("~");
                pnh.getParam("use_indices", use_indices_);
              }
             protected:
              bool use_indices_;
            };
            """,
        "src/lazy/src/lazy.cpp": """
            #include <std_msgs/String.h>
            #include "lazy/base.h"
            class Lazy : public Base {
             public:
              void start() {
                ros::NodeHandle pnh("~");
                init();
                if (use_indices_) indices_ = pnh.advertise<std_msgs::String>("indices", 1);
                out_ = pnh.advertise<std_msgs::String>("output", 1);
              }
              ros::Publisher indices_, out_;
            };
            int main(int argc, char ** argv) {
              ros::init(argc, argv, "lazy");
              Lazy().start();
            }
            """,
        "src/lazy/launch/lazy.launch": """
            <launch>
              <node pkg="lazy" type="lazy" name="plain"/>
              <node pkg="lazy" type="lazy" name="indexed">
                <param name="use_indices" value="true"/>
              </node>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  c: [lazy/launch/lazy.launch]\n",
    })
    config = _config(root)
    assert _publishers(config, "/plain") == {"output": []}
    assert _publishers(config, "/indexed") == {"indices": [], "output": []}


FALLBACK_NODE = """\
#include <ros/ros.h>
#include <sensor_msgs/MagneticField.h>
#include <sensor_msgs/Imu.h>

class Filter {
 public:
  Filter(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh) {
    if (!pnh_.getParam("use_mag", use_mag_)) use_mag_ = true;
    if (!pnh_.getParam("publish_debug", debug_)) {
      debug_ = false;
    }
    if (!pnh_.getParam("gain", gain_)) gain_ = 0.1; else gain_ = 2 * gain_;
    if (use_mag_)
      mag_ = nh_.subscribe("imu/mag", 5, &Filter::onMag, this);
    if (debug_)
      dbg_ = nh_.advertise<sensor_msgs::Imu>("imu/debug", 5);
  }
  void onMag(const sensor_msgs::MagneticField::ConstPtr& msg) {}
 private:
  ros::NodeHandle nh_, pnh_;
  bool use_mag_, debug_;
  double gain_;
  ros::Subscriber mag_;
  ros::Publisher dbg_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mag_filter");
  Filter filter(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
}
"""


def test_a_default_assigned_when_the_read_fails_is_no_other_write(write_tree):
    """imu_tools: ``if (!pnh.getParam("use_mag", use_mag_)) use_mag_ = true;`` (also in
    braces) runs only when the parameter is not there, so the member still holds the
    parameter and ``if (use_mag_)`` is decided by the launch value or that default; an
    ``else`` that writes the member again leaves it undecided."""
    root = write_tree({
        "src/mag/package.xml": package_xml("mag"),
        "src/mag/CMakeLists.txt": "project(mag)\nadd_executable(mag src/mag.cpp)\n",
        "src/mag/src/mag.cpp": FALLBACK_NODE,
        "src/mag/launch/mag.launch": (
            '<launch><node pkg="mag" type="mag" name="off">'
            '<param name="use_mag" value="false"/></node>'
            '<node pkg="mag" type="mag" name="on"/></launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [mag/launch/mag.launch]\n",
    })
    result = extract_cpp([str(root / "src/mag/src/mag.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert {c.name: (c.variable, c.default) for c in result.calls if c.kind == "read"} == {
        "~use_mag": ("use_mag_", True), "~publish_debug": ("debug_", False),
        "~gain": (None, 0.1)}
    config = _config(root)
    links = {(link.node.name, link.kind, link.rosname.full): [c.text for c in link.conditions]
             for link in config.links if link.kind in ("publish", "subscribe")}
    assert links == {("/on", "subscribe", "/imu/mag"): []}


SWITCHED_OFF_NODE = """\
#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <sstream>
#include <vector>

// an operator<< of the package's own (ros_filter_utilities.h): the chain below, with an
// operand of type T, is a call clang leaves unresolved in the class template
std::ostream& operator<<(std::ostream& os, const std::vector<double>& values);

template <class T>
class Filter {
 public:
  Filter() : use_control_(false), mode_(0) {}
  void load() {
    ros::NodeHandle pnh("~");
    std::vector<int> config;
    pnh.param("use_control", use_control_, false);
    if (use_control_) {
      if (!pnh.getParam("control_config", config)) {
        use_control_ = false;
      }
    }
    pnh.param("mode", mode_, 0);
    if (mode_ > 3) mode_ = 3;
    debug_ << "size " << inputs_.size() << " use_control " << use_control_;
  }
  void start() {
    ros::NodeHandle nh;
    if (use_control_) sub_ = nh.subscribe("cmd_vel", 1, &Filter::onTwist, this);
    if (mode_ == 3) pub_ = nh.advertise<geometry_msgs::Twist>("mode_three", 1);
  }
  void onTwist(const geometry_msgs::Twist::ConstPtr& msg) {}
 private:
  bool use_control_;
  int mode_;
  T inputs_;
  std::ostringstream debug_;
  ros::Subscriber sub_;
  ros::Publisher pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "ekf");
  Filter<std::vector<int>> f;
  f.load();
  f.start();
  ros::spin();
}
"""


def test_a_member_the_code_also_sets_to_a_constant_is_decided_when_they_agree(write_tree):
    """robot_localization's RosFilter: ``param("use_control", useControl_, false)`` and
    ``useControl_ = false;`` when the control config is bad (ros_filter.cpp:924-951),
    and prints it in a stream chain clang cannot resolve in the class template (1046):
    with use_control unset the member is false whatever runs, so cmd_vel is not
    subscribed; set true, it may still be switched off: undecided. ``mode_ = 3`` after
    ``param("mode", mode_, 0)`` agrees with neither: undecided."""
    root = write_tree({
        "src/ekf/package.xml": package_xml("ekf"),
        "src/ekf/CMakeLists.txt": "project(ekf)\nadd_executable(ekf src/ekf.cpp)\n",
        "src/ekf/src/ekf.cpp": SWITCHED_OFF_NODE,
        "src/ekf/launch/ekf.launch": (
            '<launch><node pkg="ekf" type="ekf" name="unset"/>'
            '<node pkg="ekf" type="ekf" name="on">'
            '<param name="use_control" value="true"/></node></launch>\n'),
        "project.yaml": "project: p\nconfigurations:\n  c: [ekf/launch/ekf.launch]\n",
    })
    result = extract_cpp([str(root / "src/ekf/src/ekf.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert {c.name: (c.variable, c.also) for c in result.calls if c.kind == "read"} == {
        "~use_control": ("use_control_", [False]), "~control_config": (None, None),
        "~mode": ("mode_", [3])}
    config = _config(root)
    links = {(link.node.name, link.kind, link.rosname.full): [c.text for c in link.conditions]
             for link in config.links if link.kind in ("publish", "subscribe")}
    assert links == {("/on", "subscribe", "/cmd_vel"): ["use_control_"],
                     ("/unset", "publish", "/mode_three"): ["mode_ == 3"],
                     ("/on", "publish", "/mode_three"): ["mode_ == 3"]}


LOCAL_NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Mpc : public rclcpp::Node
{
public:
  Mpc() : rclcpp::Node("mpc")
  {
    const std::string vehicle_model_type = declare_parameter<std::string>("vehicle_model_type");
    if (vehicle_model_type == "dynamics") {
      mass_ = declare_parameter<double>("vehicle.mass_fl");
    }
    const bool debug = declare_parameter("publish_debug", false);
    if (debug) {
      pub_ = create_publisher<std_msgs::msg::String>("debug", 1);
    }
    bool changed = declare_parameter("changed", true);
    changed = !changed;
    if (changed) {
      other_ = create_publisher<std_msgs::msg::String>("changed", 1);
    }
  }
  void other()
  {
    bool debug = true;  // the same name in another function: no parameter
    if (debug) {
      third_ = create_publisher<std_msgs::msg::String>("always", 1);
    }
  }
  double mass_ = 0.0;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, other_, third_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Mpc>();
  node->other();
  rclcpp::spin(node);
}
"""

LOCAL_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ex', executable='mpc', name='mpc',
             parameters=[{'vehicle_model_type': 'kinematics', 'changed': True}]),
    ])
"""


def test_a_condition_over_a_local_that_holds_a_parameter(write_tree) -> None:
    """Autoware's MPC lateral controller reads ``vehicle.mass_fl`` and five more only
    ``if (vehicle_model_type == "dynamics")``, a local it declared the parameter into
    (mpc_lateral_controller.cpp:170-188); its configuration says "kinematics", so those
    reads are not made there (they were "read but never set" warnings). A local written
    again, or one of another function, is no parameter's."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(mpc src/node.cpp)\n",
        "src/ex/src/node.cpp": LOCAL_NODE,
        "src/ex/launch/ex.launch.py": LOCAL_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    found = extract_cpp([str(root / "src/ex/src/node.cpp")], scan([str(root / "src")]),
                        cache_dir=None)
    held = {c.name: [k.parameters for k in c.conditions] for c in found.calls
            if c.kind in ("declare", "publish") and c.conditions}
    assert held == {
        "vehicle.mass_fl": [(("vehicle_model_type", "vehicle_model_type"),)],
        "debug": [(("debug", "publish_debug"),)],
        "changed": [None],
        "always": [None],
    }
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (config,) = model.configurations
    names = {(link.kind, link.rosname.full, tuple(str(c) for c in link.conditions))
             for link in config.links if link.kind in ("read", "declare", "publish")
             and "parameter_events" not in link.rosname.full
             and "rosout" not in link.rosname.full}
    assert ("read", "/mpc/vehicle.mass_fl", ()) not in names
    assert not [n for n in names if "mass_fl" in n[1]]  # kinematics: not read
    assert ("publish", "/debug", ()) not in names  # false by the declared default
    assert not [n for n in names if n[1] == "/debug"]
    assert ("publish", "/changed", ("if (changed)",)) in names  # undecided
    assert ("publish", "/always", ("if (debug)",)) in names


UNKNOWN_NAME_NODE = """
#include <cstdlib>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Zone : public rclcpp::Node
{
public:
  Zone() : rclcpp::Node("zone")
  {
    visualize_ = declare_parameter(std::string(std::getenv("ZONE")) + ".visualize", false);
    if (visualize_) {
      pub_ = create_publisher<std_msgs::msg::String>("zone_markers", 1);
    }
  }
  bool visualize_ = false;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Zone>());
}
"""


def test_a_member_read_from_a_name_not_known_decides_nothing(write_tree) -> None:
    """navigation2's exclusion zones read ``visualize_`` from ``zone_name_ +
    ".visualize"``, a name not known here: the configuration may set the real one, so
    ``if (visualize_)`` is not decided by the read's default (its publisher was dropped
    as "false")."""
    root = write_tree({
        "src/ex/package.xml": package_xml("ex", "ament_cmake"),
        "src/ex/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(ex)\n"
                                 "add_executable(zone src/node.cpp)\n",
        "src/ex/src/node.cpp": UNKNOWN_NAME_NODE,
        "src/ex/launch/ex.launch.py": LOCAL_LAUNCH.replace("'mpc'", "'zone'").replace(
            "parameters=[{'vehicle_model_type': 'kinematics', 'changed': True}]", ""),
        "project.yaml": "project: p\nconfigurations:\n  c: [ex/launch/ex.launch.py]\n"})
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))
    (config,) = model.configurations
    assert [(link.rosname.full, [str(c) for c in link.conditions]) for link in config.links
            if link.kind == "publish" and "markers" in link.rosname.full] == [
        ("/zone_markers", ["if (visualize_)"])]


NODE_PRESENCE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <map>
    #include <string>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "marker");
      ros::NodeHandle nh("~");
      ros::NodeHandle* handle = &nh;
      std::map<std::string, double> scale, top;
      double r = 1.0, left = 1.0;
      if (nh.getParam("linear_scale", scale)) {
        nh.getParam("max_velocity", top);
      } else {
        nh.param<double>("max_velocity", top["x"], 1.0);
      }
      if (handle->hasParam("radius_multiplier")) {
        nh.getParam("radius_multiplier", r);
      } else {
        nh.param("left_multiplier", left, 1.0);
      }
      ros::Publisher shown;
      if (!ros::param::has("~quiet")) shown = nh.advertise<std_msgs::String>("shown", 1);
      std::map<std::string, int> axes;
      std::map<std::string, std::map<std::string, double>> turbo;
      if (nh.getParam("axis", axes)) {
        nh.getParam("turbo", turbo["x"]);
      } else {
        nh.param<double>("turbo", turbo["x"]["x"], 2.0);
      }
      ros::spin();
    }
    """


def test_a_condition_testing_whether_a_parameter_is_there_is_decided(write_tree):
    """interactive_marker_twist_server (marker_server.cpp:54-64): ``if
    (nh.getParam("linear_scale", map)) { nh.getParam("max_positive_linear_velocity", m);
    } else { nh.param<double>(.., 1.0); }``. With linear_scale set nowhere, and nothing
    unseen that could set it, getParam is false: the reads without a default are not
    made (they were a false parameter-read-not-set); hasParam of a parameter the launch
    sets is true (diff_drive_controller's wheel_radius_multiplier). getParam into a
    ``std::map`` (a ``dict`` read) of a parameter set to a number is false, as roscpp
    fills a map from a dictionary only (teleop_twist_joy.cpp:89-99 with jackal's
    ``axis_angular: 0``: scale_angular_turbo is read with its default). A parameter that
    a file not read may set (``$(arg f)``) leaves it undecided."""
    root = write_tree({
        "src/marker/package.xml": package_xml("marker"),
        "src/marker/CMakeLists.txt": "project(marker)\nadd_executable(marker src/m.cpp)\n",
        "src/marker/src/m.cpp": NODE_PRESENCE,
        "src/marker/launch/plain.launch": """
            <launch>
              <node pkg="marker" type="marker" name="marker">
                <param name="radius_multiplier" value="1.0"/>
                <param name="axis" value="1"/>
              </node>
            </launch>
            """,
        "src/marker/launch/unseen.launch": """
            <launch>
              <arg name="f" default="$(env NOT_SET_ANYWHERE)"/>
              <node pkg="marker" type="marker" name="marker">
                <rosparam command="load" file="$(find marker)/config/$(arg f).yaml"/>
              </node>
            </launch>
            """,
        "project.yaml": "project: p\nconfigurations:\n  plain: [marker/launch/plain.launch]\n"
                        "  unseen: [marker/launch/unseen.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                    Options(cache_dir=None))

    def reads(config):
        return sorted((link.rosname.full, link.location.line, bool(link.conditions))
                      for link in config.links if link.kind == "read")
    plain = model.configuration("plain")
    assert reads(plain) == [
        ("/marker/axis", 26, False),
        ("/marker/linear_scale", 12, False),  # the test itself
        ("/marker/max_velocity", 15, False),  # else: no condition left
        ("/marker/quiet", 23, False),
        ("/marker/radius_multiplier", 17, False),
        ("/marker/radius_multiplier", 18, False),
        ("/marker/turbo", 29, False)]  # else: the read with a default
    assert _publishers(plain, "/marker") == {"shown": []}
    said = [d.message for d in plain.diagnostics if d.code == "CONDITION_FALSE"]
    assert any("no read /marker/max_velocity" in m and "getParam" in m for m in said)
    assert any("no read /marker/left_multiplier" in m for m in said)
    findings = [f for f in run_catalogue(model) if f.rule == "parameter-read-not-set"]
    assert findings == []
    unseen = model.configuration("unseen")
    assert ("/marker/max_velocity", 13, True) in reads(unseen)
    assert ("/marker/turbo", 27, True) in reads(unseen)
    types = {(link.rosname.full, link.location.line): link.call.type for link in plain.links
             if link.kind == "read"}
    assert types[("/marker/axis", 26)] == "dict"
    assert _publishers(unseen, "/marker") == {"shown": ['!ros::param::has("~quiet")']}


MODE_NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char** argv) {
  ros::init(argc, argv, "gps");
  ros::NodeHandle nh;
  std::string node_name = ros::this_node::getName();
  std::string mode;
  if (!nh.getParam(node_name + "/mode", mode)) { ROS_ERROR("no mode"); }
  ros::Publisher pub;
  if (mode == "base") {
    pub = nh.advertise<std_msgs::String>("corrections", 5);
  } else if (mode == "rover") {
    pub = nh.advertise<std_msgs::String>("rover_status", 5);
  }
  ros::spin();
  return 0;
}
"""


def test_a_local_holding_a_private_parameter_read_through_the_node_name(write_tree):
    """autorally's GPS node reads ``getName() + "/mode"`` (``~/mode``) into a local and
    tests ``mode == "base"``: the read is the call ``~mode``, the condition held
    ``~/mode``, and the two names never met, so the rover's base-station publisher
    stayed (a false multiple-publishers with the real base station's relay)."""
    root = write_tree({
        "src/gps/package.xml": package_xml("gps"),
        "src/gps/CMakeLists.txt": "project(gps)\nadd_executable(gps src/gps.cpp)\n",
        "src/gps/src/gps.cpp": MODE_NODE,
        "src/gps/launch/gps.launch": (
            '<launch><node pkg="gps" type="gps" name="rover">'
            '<param name="mode" value="rover"/></node></launch>'),
        "project.yaml": "project: p\nconfigurations:\n  c: [gps/launch/gps.launch]\n",
    })
    config = _config(root)
    assert _publishers(config, "/rover") == {"rover_status": []}


def test_a_private_parameter_of_a_node_in_an_unknown_namespace_decides(write_tree):
    # kr_autonomous_flight's ukf.launch: <group ns="$(arg robot)"> whose default is
    # $(env EMU_ROBOT_NAME), the fla_ukf nodelet given <param name="enable_cam"
    # value="false"/>: the node is /?/fla_ukf, its parameter /?/fla_ukf/enable_cam, the
    # one unknown part its own name's; a shared name with ? still decides nothing
    root = _workspace(write_tree)
    (root / "src/gated/launch/gated.launch").write_text("""
    <launch>
      <arg name="robot" default="$(env HAROS_TEST_UNSET_ROBOT)"/>
      <group ns="$(arg robot)">
        <node pkg="gated" type="gated" name="gated">
          <param name="from_launch" value="true"/>
          <param name="publish_status" value="false"/>
        </node>
      </group>
    </launch>
    """)
    config = _config(root)
    gated = _publishers(config, "/?/gated")
    assert "status" not in gated and gated["quiet"] == [] and gated["launched"] == []
    assert "debug" not in gated  # the default, false
    # the launch's setting and the node's read are one parameter
    status = [p for p in config.parameters if p.name == "/?/gated/publish_status"]
    assert len(status) == 1 and status[0].set_by_launch and status[0].readers


def test_only_a_node_of_known_own_name_owns_its_unknown_parameters():
    from haros_arch.model.rosname import own_unknown

    assert own_unknown("/?/gated", "/?/gated/publish_status")
    assert not own_unknown("/?/gated", "/?/gated/?/x")
    assert not own_unknown("/?", "/?/enable_stamped_cmd_vel")  # several nodes may be /?
    assert not own_unknown("/robot1/?", "/robot1/?/x")
    assert not own_unknown("/robot1/gated", "/robot1/gated/x")  # nothing unknown
