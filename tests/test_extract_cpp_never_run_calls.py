"""A call made in code the node never runs is not the node's: a non-virtual method or
free function that no file of the node calls, takes the address of or may call where the
parse left errors, and, at any depth, one called only from such functions. HKUST
Fast-Planner's plan_env library defines ``ObjPredictor::init()``, which subscribes to
``/dynamic/pose_<i>``; fast_planner_node links the library and never calls it (nor
constructs an ObjPredictor), yet got the subscriptions. What may still run keeps its
calls: a method the node's code calls, a virtual method (a host or a base may call
it), a callback whose address is taken (wherever that is), a method of a class exported
for a plugin loader, a function whose name the code around a parse error holds."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
namespace p {
class Predictor {
 public:
  Predictor();
  explicit Predictor(ros::NodeHandle& node);
  void init();
  void setup();
  void relay();
  void deep();
  void used();
  virtual void hook();
  void callback(const std_msgs::String::ConstPtr& msg);
 private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  ros::Publisher pub_, out_;
  int num_;
};
void free_dead();
void free_chain();
void free_used();
}  // namespace p
"""
LIBRARY = """#include "p/pred.h"
namespace p {
Predictor::Predictor() {}
Predictor::Predictor(ros::NodeHandle& node) { nh_ = node; }
void Predictor::init() {
  nh_.param("/prediction/obj_num", num_, 5);
  sub_ = nh_.subscribe("/dynamic/obj", 10, &Predictor::callback, this);
  setup();
}
void Predictor::setup() { pub_ = nh_.advertise<std_msgs::String>("/dynamic/setup", 1); }
void Predictor::relay() { deep(); }
void Predictor::deep() { pub_ = nh_.advertise<std_msgs::String>("/dynamic/deep", 1); }
void Predictor::used() { pub_ = nh_.advertise<std_msgs::String>("/pred/used", 1); }
void Predictor::hook() { pub_ = nh_.advertise<std_msgs::String>("/pred/hook", 1); }
void Predictor::callback(const std_msgs::String::ConstPtr& msg) {
  out_ = nh_.advertise<std_msgs::String>("/pred/from_callback", 1);
}
void free_dead() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/free/dead", 1);
  free_chain();
}
void free_chain() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/free/chain", 1);
}
void free_used() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/free/used", 1);
}
}  // namespace p
"""
NODE = """#include "p/pred.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "planner");
  ros::NodeHandle nh("~");
  p::Predictor pred(nh);
  pred.used();
  p::free_used();
  ros::spin();
}
"""
CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(p)
find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)
catkin_package()
include_directories(include)
add_library(pred src/pred.cpp)
add_executable(node src/node.cpp)
target_link_libraries(node pred)
"""


def _names(write_tree, node: str = NODE, library: str = LIBRARY,
           header: str = HEADER) -> set[str]:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/CMakeLists.txt": CMAKE,
                       "p/include/p/pred.h": header,
                       "p/src/pred.cpp": library,
                       "p/src/node.cpp": node})
    sources = [str(root / "p" / "src" / name) for name in ("node.cpp", "pred.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    return {c.name for c in result.calls}


def test_calls_of_functions_the_node_never_runs_are_not_its(write_tree) -> None:
    names = _names(write_tree)
    assert {"/pred/used", "/free/used", "/pred/hook", "/pred/from_callback"} <= names, names
    # (``deep`` is called by ``relay`` alone, which makes no call and nothing calls)
    assert not {"/prediction/obj_num", "/dynamic/obj", "/dynamic/setup", "/free/dead",
                "/free/chain", "/dynamic/deep"} & names, names


CHAIN_HEADER = HEADER.replace("}  // namespace p\n", """
class Chain {
 public:
  Chain() { defaulted(); }
  Chain(ros::NodeHandle& node, int k) : nh_(node) { from_unbuilt(); }
  explicit Chain(ros::NodeHandle& node) : nh_(node) { built(); }
  void defaulted() { nh_.advertise<std_msgs::String>("/chain/defaulted", 1); }
  void from_unbuilt() { nh_.advertise<std_msgs::String>("/chain/from_unbuilt", 1); }
  void built() { nh_.advertise<std_msgs::String>("/chain/built", 1); }
  void slot() { nh_.advertise<std_msgs::String>("/chain/slot", 1); }
  void never() { nh_.advertise<std_msgs::String>("/chain/never", 1); }
  ros::NodeHandle nh_;
};
class Factory {
 public:
  explicit Factory(ros::NodeHandle& node) : nh_(node) { made(); }
  void made() { nh_.advertise<std_msgs::String>("/factory/made", 1); }
  ros::NodeHandle nh_;
};
void connected();
}  // namespace p
""").replace("#include <ros/ros.h>", "#include <ros/ros.h>\n#include <QObject>")
CHAINED = LIBRARY.replace("}  // namespace p\n", """
void connected() { const char* s = SLOT(slot()); (void)s; }
}  // namespace p
""")
CHAIN_NODE = NODE.replace("p::free_used();", """p::free_used();
  auto chain = std::make_shared<p::Chain>(nh);
  p::connected();""")


def test_what_a_constructor_or_qt_may_run_keeps_its_calls(write_tree) -> None:
    names = _names(write_tree, CHAIN_NODE, CHAINED, CHAIN_HEADER)
    # a default constructor may run unwritten (a loader's, a member's), and so what it
    # calls; a Qt slot named in a SLOT() string may run; a constructor make_shared
    # builds runs; so may one of a class the node's files build nowhere (a library's
    # template may: BehaviorTree.CPP's registerNodeType<C>)
    assert {"/chain/defaulted", "/chain/slot", "/chain/built", "/factory/made"} <= names, (
        names)
    # a constructor that takes arguments and that nothing calls, of a class built by
    # another, runs nothing
    assert not {"/chain/from_unbuilt", "/chain/never"} & names, names


def test_a_call_the_parse_may_hide_keeps_the_function(write_tree) -> None:
    node = NODE.replace("pred.used();", "pred.used();\n  pred.init(undeclared_thing);")
    names = _names(write_tree, node)
    assert {"/dynamic/obj", "/dynamic/setup"} <= names, names


EXPORTED = LIBRARY.replace("}  // namespace p\n", """
class Exported : public Predictor {
 public:
  void setup() { ros::NodeHandle n; n.advertise<std_msgs::String>("/exported/setup", 1); }
};
}  // namespace p
PLUGINLIB_EXPORT_CLASS(p::Exported, p::Predictor)
""").replace('#include "p/pred.h"', '#include "p/pred.h"\n#include <pluginlib/class_list_macros.h>')


def test_code_without_a_main_keeps_every_call(write_tree) -> None:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/CMakeLists.txt": CMAKE,
                       "p/include/p/pred.h": HEADER,
                       "p/src/pred.cpp": EXPORTED})
    result = extract_cpp([str(root / "p" / "src" / "pred.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    names = {c.name for c in result.calls}
    # a plugin's host may call any method of its class and bases; code whose start is
    # not read may call any function
    assert {"/exported/setup", "/pred/used", "/pred/hook", "/dynamic/obj", "/free/dead",
            "/free/chain"} <= names, names


SHARED = LIBRARY.replace("void free_used() {", """void shared_sub() {
  ros::NodeHandle n;
  n.advertise<std_msgs::String>("/shared/out", 1);
}
void free_conditional(bool on) {
  if (on) shared_sub();
}
void free_unconditional() { shared_sub(); }
void free_used() {""")
SHARED_NODE = NODE.replace("p::free_used();", """p::free_used();
  bool on = false;
  nh.param("on", on, false);
  p::free_conditional(on);""")
SHARED_HEADER = HEADER.replace("void free_used();", """void free_used();
void free_conditional(bool on);
void free_unconditional();""")


def test_a_site_in_code_never_run_gives_no_condition(write_tree) -> None:
    root = write_tree({"p/package.xml": package_xml("p", "catkin"),
                       "p/CMakeLists.txt": CMAKE,
                       "p/include/p/pred.h": SHARED_HEADER,
                       "p/src/pred.cpp": SHARED,
                       "p/src/node.cpp": SHARED_NODE})
    sources = [str(root / "p" / "src" / name) for name in ("node.cpp", "pred.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    # shared_sub runs only under ``if (on)``: the unconditional site is in a function
    # nothing calls
    made = [c for c in result.calls if c.name == "/shared/out"]
    assert len(made) == 1 and made[0].conditions, made


def test_a_process_that_loads_plugins_keeps_the_calls(write_tree) -> None:
    # a plugin loaded into the process may call any method of an object it is handed
    # (move_group's capabilities call PlanExecution::planAndExecute, which nothing of
    # move_group's own files calls)
    node = NODE.replace('#include "p/pred.h"', '#include "p/pred.h"\n'
                        "#include <pluginlib/class_loader.h>").replace(
        "pred.used();", """pred.used();
  pluginlib::ClassLoader<p::Predictor> loader("p", "p::Predictor");
  boost::shared_ptr<p::Predictor> plugin = loader.createInstance("p/Plugin");""")
    names = _names(write_tree, node)
    assert {"/dynamic/obj", "/dynamic/setup", "/prediction/obj_num"} <= names, names


def test_a_method_called_on_a_temporary_runs(write_tree) -> None:
    # ``Driver().start(nh)``: the constructor's call and the method's start at one
    # place; both are call sites (kuka_eki_hw_interface's driver)
    node = NODE.replace("pred.used();", "p::Predictor(nh).init();")
    names = _names(write_tree, node)
    assert {"/dynamic/obj", "/dynamic/setup", "/prediction/obj_num"} <= names, names
