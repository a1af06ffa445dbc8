"""What a C++ function does after ``if (TEST) return;`` runs only when TEST is false, and
a parameter whose absence makes the function fail is required: the extraction's
conditions and ``tested`` say so (costmap_2d's ``move_parameter``, cob_frame_tracker's
``if (nh.hasParam("target_frame")) {..} else { ROS_ERROR(..); return false; }``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

GUARDS = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
class Tracker {
 public:
  bool initialize() {
    ros::NodeHandle nh_tracker("frame_tracker");
    if (nh_tracker.hasParam("update_rate")) {
      nh_tracker.getParam("update_rate", rate_);
    } else {
      rate_ = 68.0;
    }
    if (nh_tracker.hasParam("target_frame")) {
      nh_tracker.getParam("target_frame", target_);
    } else {
      ROS_ERROR("No target_frame specified. Aborting!");
      return false;
    }
    if (!nh_.getParam("chain_tip", tip_)) {
      ROS_ERROR("no tip");
      return false;
    }
    if (!nh_.getParam("optional_a", a_) || !nh_.getParam("optional_b", b_)) {
      ROS_WARN("defaults");
      a_ = "a";
    }
    pub_ = nh_.advertise<std_msgs::String>("status", 1);
    return true;
  }
  void move(ros::NodeHandle& old_h, ros::NodeHandle& new_h, const std::string& name) {
    if (!old_h.hasParam(name)) return;
    XmlRpc::XmlRpcValue value;
    old_h.getParam(name, value);
    new_h.setParam(name, value);
  }
  void each(const std::vector<std::string>& topics) {
    for (size_t i = 0; i < topics.size(); ++i) {
      if (topics[i] == "skip") continue;
      subs_.push_back(nh_.subscribe(topics[i], 1, &Tracker::cb, this));
    }
  }
  void cb(const std_msgs::String::ConstPtr&) {}
  void lazy() {
    if (initialized_) {
      ROS_WARN("already");
      return;
    }
    late_ = nh_.advertise<std_msgs::String>("late", 1);
    initialized_ = true;
  }
  void modes(const std::string& mode) {
    if (mode == "off") {
      ROS_INFO("off");
      return;
    }
    if (mode != "a" && mode != "b") throw std::runtime_error("bad mode");
    mode_pub_ = nh_.advertise<std_msgs::String>("mode", 1);
  }
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_, late_, mode_pub_;
  std::vector<ros::Subscriber> subs_;
  double rate_;
  std::string target_, tip_, a_, b_;
  bool initialized_ = false;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "tracker");
  ros::NodeHandle pnh("~");
  Tracker t;
  if (!t.initialize()) return 1;
  ros::NodeHandle a("a"), b("b");
  t.move(a, b, "x");
  t.lazy();
  t.modes("a");
  t.each(std::vector<std::string>{"x"});
  ros::spin();
}
"""


def _calls(tmp_path):
    source = tmp_path / "n.cpp"
    source.write_text(GUARDS)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    return result.calls


def _conditions(call) -> list[tuple[str, str]]:
    return [(c.statement, c.text) for c in call.conditions]


def test_what_follows_an_early_return_runs_under_the_tests_else(tmp_path):
    calls = _calls(tmp_path)
    by = {(c.kind, c.name): c for c in calls}
    # costmap_2d's move_parameter: copied only when the old handle has it (the
    # hasParam runs always, and the read after it is one with it)
    assert _conditions(by["write", "b/x"]) == [("else", "!old_h.hasParam(name)")]
    assert _conditions(by["read", "a/x"]) == []
    # a loop's ``continue``: the subscription is made for the topics not skipped
    subscribe = next(c for c in calls if c.kind == "subscribe")
    assert ("else", 'topics[i] == "skip"') in _conditions(subscribe)
    # a return that ends the function on purpose (not a failure)
    assert _conditions(by["publish", "mode"]) == [("else", 'mode == "off"')]


def test_a_failure_or_a_lazy_initialisation_adds_no_condition(tmp_path):
    by = {(c.kind, c.name): c for c in _calls(tmp_path)}
    # ``return false`` after an error: the function's work when it succeeds
    assert _conditions(by["publish", "status"]) == []
    # ``if (initialized_) { ..; return; }`` before ``initialized_ = true``
    assert _conditions(by["publish", "late"]) == []


def test_a_parameter_whose_absence_fails_is_required(tmp_path):
    calls = [c for c in _calls(tmp_path) if c.kind == "read"]
    reads = {(c.name, c.location.line): (c.tested, _conditions(c)) for c in calls}
    lines = GUARDS.splitlines()

    def line(text: str) -> int:
        return next(i for i, t in enumerate(lines, 1) if text in t)

    # a fallback in the else: the read handles absence, under its test
    assert reads["frame_tracker/update_rate", line('getParam("update_rate"')] == (
        False, [("if", 'nh_tracker.hasParam("update_rate")')])
    # the else aborts: the read is made whenever the function goes on, untested
    assert reads["frame_tracker/target_frame", line('getParam("target_frame"')] == (
        False, [])
    assert reads["frame_tracker/target_frame", line('hasParam("target_frame"')] == (
        False, [])
    # ``if (!nh.getParam(..)) { ROS_ERROR(..); return false; }``: required
    assert reads["chain_tip", line('"chain_tip"')] == (False, [])
    # a fallback: both reads tested
    assert reads["optional_a", line('"optional_a"')][0] is True
    assert reads["optional_b", line('"optional_a"')][0] is True


COPIER = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
void move_parameter(ros::NodeHandle& old_h, ros::NodeHandle& new_h, const std::string& name) {
  if (!old_h.hasParam(name)) return;
  XmlRpc::XmlRpcValue value;
  old_h.getParam(name, value);
  new_h.setParam(name, value);
}
bool init(ros::NodeHandle& nh) {
  std::string target;
  if (nh.hasParam("target_frame")) {
    nh.getParam("target_frame", target);
  } else {
    ROS_ERROR("No target_frame specified. Aborting!");
    return false;
  }
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "copier");
  ros::NodeHandle pnh("~"), layer("~layer");
  move_parameter(pnh, layer, "given");
  move_parameter(pnh, layer, "missing");
  if (!init(pnh)) return 1;
  ros::spin();
}
"""

COPIER_LAUNCH = """<launch>
  <node pkg="copier" type="copier" name="copier"><param name="given" value="1"/></node>
</launch>
"""


def _model(write_tree):
    from conftest import package_xml

    from haros_arch.pipeline import Options, analyse
    from haros_arch.project import load

    root = write_tree({
        "src/copier/package.xml": package_xml("copier"),
        "src/copier/CMakeLists.txt": "project(copier)\nadd_executable(copier src/c.cpp)\n",
        "src/copier/src/c.cpp": COPIER,
        "src/copier/launch/c.launch": COPIER_LAUNCH,
        "project.yaml": "project: p\nconfigurations:\n  c: [copier/launch/c.launch]\n",
    })
    return analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None))


def test_a_copy_after_a_presence_test_of_a_passed_name_is_decided_per_call(write_tree):
    """move_parameter's copy is made for the name the launch file sets, not for the
    other: the test ``!old_h.hasParam(name)`` is the read made at the same call site."""
    config = _model(write_tree).configuration("c")
    writes = {link.rosname.full: [c.text for c in link.conditions]
              for link in config.links if link.kind == "write"}
    assert writes == {"/copier/layer/given": []}
    said = [d.message for d in config.diagnostics if d.code == "CONDITION_FALSE"]
    assert any("/copier/layer/missing" in m for m in said)


def test_a_required_parameter_not_set_is_reported(write_tree):
    """cob_frame_tracker aborts without ``target_frame``: a read the launch file does not
    set is a finding, not a handled absence."""
    from haros_arch.query.catalogue import run_catalogue

    model = _model(write_tree)
    findings = [f for f in run_catalogue(model) if f.rule == "parameter-read-not-set"]
    assert [f.message.split(" is read")[0] for f in findings] == ["/copier/target_frame"]


DECLARE_OR_GET = r"""
#include <rclcpp/rclcpp.hpp>
#include <string>
template<typename NodeT, typename T>
T declare_or_get_parameter(NodeT node, const std::string & parameter_name, const T & value)
{
  auto param_interface = node->get_node_parameters_interface();
  if (param_interface->has_parameter(parameter_name)) {
    rclcpp::Parameter param(parameter_name, value);
    param_interface->get_parameter(parameter_name, param);
    return param.get_value<T>();
  }
  return param_interface->declare_parameter(
    parameter_name, rclcpp::ParameterValue{value}).template get<T>();
}
class Server : public rclcpp::Node {
 public:
  Server() : Node("server") {
    double rate = declare_or_get_parameter(this, "rate", 1.0);
    if (has_parameter("other")) {
      return;
    }
    declare_parameter("late", 2.0);
    (void)rate;
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Server>());
}
"""


def test_a_declaration_after_returning_what_is_declared_is_no_condition(tmp_path):
    """navigation2's ``declare_or_get_parameter``: ``if (has_parameter(n)) return
    get_parameter(n);`` then ``declare_parameter(n, ..)``: after it the parameter is
    declared either way; a test of another parameter stays a condition."""
    source = tmp_path / "s.cpp"
    source.write_text(DECLARE_OR_GET)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    declared = {c.name: _conditions(c) for c in result.calls if c.kind == "declare"}
    assert declared == {"rate": [], "late": [("else", 'has_parameter("other")')]}


NOT_AGAIN = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>
class Loader {
 public:
  bool load(const std::string& file) {
    if (!always_reload_ && current_ == file) {
      return true;
    }
    pub_ = nh_.advertise<std_msgs::String>("log", 1);
    current_ = file;
    return true;
  }
  void step() {
    if (count_ > 10) return;
    other_ = nh_.advertise<std_msgs::String>("other", 1);
  }
 private:
  ros::NodeHandle nh_;
  ros::Publisher pub_, other_;
  std::string current_;
  bool always_reload_ = false;
  int count_ = 0;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "loader");
  Loader l;
  l.load("a");
  l.step();
  ros::spin();
}
"""


def test_a_guard_over_state_the_block_updates_lets_the_first_run_through(tmp_path):
    """navigation2's BT server loads a tree (and makes its logger's publisher) unless
    the same file is loaded already, and then records the file: the first load goes
    past the guard. A guard over a member the block does not set stays a condition."""
    source = tmp_path / "l.cpp"
    source.write_text(NOT_AGAIN)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert {c.name: _conditions(c) for c in result.calls if c.kind == "publish"} == {
        "log": [], "other": [("else", "count_ > 10")]}
