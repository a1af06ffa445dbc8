"""Several ROS 2 nodes in one C++ executable (``fixtures/cpp/several_nodes``): two
classes deriving from rclcpp::Node, each naming itself in its base initialiser, added to
one executor by main; or plain nodes made in free functions. Each call is made on the
node of the class (or function) it is in, and the graph makes one instance per node."""

from __future__ import annotations

import json
import os

import pytest
from conftest import FIXTURES

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.extract.cpp.cache import from_data, to_data
from haros_arch.model.conditions import Condition
from haros_arch.model.location import Location
from haros_arch.model.model import Model
from haros_arch.pipeline import Options, analyse, read_build_files
from haros_arch.project import load
from haros_arch.workspace import scan

CASE = FIXTURES / "cpp" / "several_nodes"
BASE = CASE / "src" / "rover_base" / "src"
SINGLE = CASE / "src" / "rover_single" / "src"


def extract(*paths: os.PathLike[str]) -> CppResult:
    return extract_cpp([str(p) for p in paths], scan([str(CASE)]), cache_dir=None)


def rows(result: CppResult) -> set[tuple[str, str, str | None]]:
    return {(c.kind, c.name, c.node_name) for c in result.calls}


def published(result: CppResult) -> list[str]:
    """The topics ``result``'s calls publish, sorted."""
    return sorted(topic for kind, topic, _ in rows(result) if kind == "publish")


def each_main(root, mains: tuple[str, ...], library: list[str]) -> dict[str, CppResult]:
    """Each executable ``pkg/src/<main>_main.cpp`` of the package at ``root`` extracted
    with the ``library`` sources it links."""
    workspace = scan([str(root)])
    return {name: extract_cpp([str(root / f"pkg/src/{name}_main.cpp"), *library],
                              workspace, cache_dir=None) for name in mains}


@pytest.fixture(scope="module")
def base() -> CppResult:
    return extract(BASE / "main.cpp", BASE / "base_driver.cpp", BASE / "odometry.cpp",
                   BASE / "devices.cpp")


def test_each_class_names_its_node_and_its_calls(base: CppResult) -> None:
    # files by path: base_driver.cpp, then odometry.cpp
    assert base.rosnames == ["rover_base_node", "odometry_node"]
    assert base.rosname == "rover_base_node"
    assert rows(base) == {
        ("declare", "port", "rover_base_node"),
        ("subscribe", "cmd_vel", "rover_base_node"),
        ("publish", "wheel_speed", "rover_base_node"),  # in a lambda of a method
        ("publish", "battery", "rover_base_node"),
        ("publish", "odom", "odometry_node"),
        ("subscribe", "wheel_speed", "odometry_node"),
        # a device class, constructed by the driver only, publishes on the driver's node
        ("publish", "battery_voltage", "rover_base_node"),
        # constructed by both nodes, each handing its own: made on each
        ("publish", "heartbeat", "rover_base_node"),
        ("publish", "heartbeat", "odometry_node"),
    }


def test_the_order_of_the_sources_does_not_change_the_nodes() -> None:
    again = extract(BASE / "devices.cpp", BASE / "odometry.cpp", BASE / "main.cpp",
                    BASE / "base_driver.cpp")
    assert again.rosnames == ["rover_base_node", "odometry_node"]
    assert again.rosname == "odometry_node"  # as before: the first file's name
    assert ("publish", "odom", "odometry_node") in rows(again)
    assert ("publish", "battery_voltage", "rover_base_node") in rows(again)


def test_nodes_made_in_free_functions() -> None:
    helpers = extract(SINGLE / "helpers.cpp")
    assert helpers.rosnames == ["watchdog", "helper_node", "log_node"]
    assert rows(helpers) == {("subscribe", "heartbeat", "watchdog"),
                             ("publish", "heartbeat", "helper_node"),
                             # main makes two nodes: its calls go by the handle's node
                             ("publish", "log", "log_node"),
                             ("subscribe", "log", "helper_node")}


def test_one_node_keeps_its_name_and_no_node_names() -> None:
    single = extract(SINGLE / "monitor.cpp")
    assert single.rosname == "battery_monitor"
    assert single.rosnames == []
    assert rows(single) == {("subscribe", "battery", None), ("publish", "alarm", None)}


def test_a_node_of_one_file_only_is_one_node() -> None:
    """The driver's file alone: one name, so calls carry no node name."""
    alone = extract(BASE / "base_driver.cpp")
    assert alone.rosnames == []
    assert {c.node_name for c in alone.calls} == {None}


def test_node_names_survive_the_cache(tmp_path: object) -> None:
    workspace = scan([str(CASE)])
    sources = [str(BASE / "main.cpp"), str(BASE / "base_driver.cpp"),
               str(BASE / "odometry.cpp"), str(BASE / "devices.cpp")]
    first = extract_cpp(sources, workspace, cache_dir=str(tmp_path), jobs=1)
    cached = extract_cpp(sources, workspace, cache_dir=str(tmp_path), jobs=1)
    assert cached.rosnames == first.rosnames == ["rover_base_node", "odometry_node"]
    assert rows(cached) == rows(first)
    under = Condition("enabled_", location=Location("rover_base", "src/main.cpp", 9))
    data = to_data([], None, [], [], [("rover::Odometry", "odometry_node")],
                   [("rover::BaseDriver", "rover::devices::Battery")], ["Battery", "vendor"],
                   [("rover::Odometry", (under,))], [("main()", "rover::spin_all()")],
                   ["main()", "rover::spin_all()"], ["rover::spin_all()"],
                   [("vendor", "rover::spin_all()")],
                   [("rover::spin_all()", "vendor::Bus")], ["Battery", "make_impl"],
                   [("rover::Odometry", "rover::Odometry"), ("rover::Odometry", "rover::Base")],
                   ["rover::Odometry", ""], [("rover::BaseDriver", "rover::Publishers")])
    assert from_data(json.loads(json.dumps(data)))[4:] == (
        [("rover::Odometry", "odometry_node")],
        [("rover::BaseDriver", "rover::devices::Battery")], ["Battery", "vendor"],
        [("rover::Odometry", (under,))], [("main()", "rover::spin_all()")],
        ["main()", "rover::spin_all()"], ["rover::spin_all()"],
        [("vendor", "rover::spin_all()")],
        [("rover::spin_all()", "vendor::Bus")], ["Battery", "make_impl"],
        [("rover::Odometry", "rover::Odometry"), ("rover::Odometry", "rover::Base")],
        ["rover::Odometry", ""], [("rover::BaseDriver", "rover::Publishers")])
    with pytest.raises(TypeError):
        from_data({**data, "registered": [["rover::Odometry", None]]})
    with pytest.raises(TypeError):
        from_data({**data, "loads_in": [None]})
    with pytest.raises(TypeError):
        from_data({**data, "unseen_in": [["vendor", None]]})
    with pytest.raises(TypeError):
        from_data({**data, "passed": [["rover::spin_all()", 3]]})
    with pytest.raises(TypeError):
        from_data({**data, "hidden": [None]})
    with pytest.raises(TypeError):
        from_data({**data, "handed": [3]})
    with pytest.raises(TypeError):
        from_data({**data, "unseen": [None]})
    with pytest.raises(TypeError):
        from_data({**data, "node_names": [["rover::Odometry", 3]]})
    with pytest.raises(TypeError):
        from_data({**data, "constructions": [[None, "rover::devices::Battery"]]})
    with pytest.raises(TypeError):
        from_data({**data, "uses": [["main()", 3]]})
    with pytest.raises(TypeError):
        from_data({**data, "defines": [None]})


@pytest.fixture(scope="module")
def model() -> Model:
    return analyse(load(str(CASE / "project.yaml")), {"PATH": os.environ.get("PATH", "")},
                   Options(cache_dir=None))


def links(model: Model, node: str) -> list[tuple[str, str]]:
    config = model.configuration("base")
    return sorted((link.kind, link.name) for link in config.links if link.node.name == node)


def test_the_executable_has_two_node_instances(model: Model) -> None:
    node = {n.executable: n for p in model.packages for n in p.nodes}["base_ros"]
    assert node.rosnames == ["rover_base_node", "odometry_node"]
    config = model.configuration("base")
    assert [n.name for n in config.nodes] == ["/rover_base_node", "/odometry_node"]
    assert links(model, "/odometry_node") == [
        ("publish", "/heartbeat"), ("publish", "/odom"), ("subscribe", "/wheel_speed")]
    driver = links(model, "/rover_base_node")
    assert ("subscribe", "/cmd_vel") in driver and ("publish", "/battery") in driver
    assert ("publish", "/wheel_speed") in driver and ("publish", "/odom") not in driver
    assert ("publish", "/battery_voltage") in driver
    assert ("publish", "/heartbeat") in driver  # both nodes build a Heartbeat
    topic = next(t for t in config.topics if t.name == "/wheel_speed")
    assert [p.node.name for p in topic.publishers] == ["/rover_base_node"]
    assert [s.node.name for s in topic.subscribers] == ["/odometry_node"]


def test_constructions_in_a_cycle_give_no_node() -> None:
    from haros_arch.extract.cpp import _node_of

    owners = {"A": ["a"], "B": ["b"]}
    made_by = {"X": ["Y"], "Y": ["X"], "Z": ["A", "W"], "W": ["A"]}
    names = ["a", "b"]
    assert _node_of("X", owners, made_by, names, {}, 0) is None
    assert _node_of("Z", owners, made_by, names, {}, 0) == "a"  # A directly and via W
    assert _node_of("Z", owners, {"Z": ["A", "B"]}, names, {}, 0) is None
    assert _node_of("A", owners, made_by, [], {}, 0) is None  # one node: no node names


def test_a_component_library_is_one_node_per_plugin() -> None:
    """The same classes built as a component library: each is loaded as a plugin of its
    own, so the library's node has no process nodes and its calls no node names."""
    from haros_arch.extract import extract_nodes
    from haros_arch.model.source import Node

    sources = [str(BASE / name) for name in ("base_driver.cpp", "odometry.cpp")]
    library = Node("rover_base", "rover::Odometry", "component", "cpp", sources)
    process = Node("rover_base", "base_ros", "executable", "cpp", list(sources))
    extract_nodes([library, process], scan([str(CASE)]), cache_dir=None)
    assert process.rosnames == ["rover_base_node", "odometry_node"]
    assert {c.node_name for c in process.calls} == {  # the heartbeat on both
        "rover_base_node", "odometry_node"}
    assert library.rosnames == [] and library.calls
    assert {c.node_name for c in library.calls} == {None}


def test_a_node_that_renames_itself_is_no_node_of_the_process(tmp_path) -> None:
    """nav2's internal client nodes: made as "_" with their own ``__node:=`` argument,
    which wins over the process's (and a launch ``name=``), so they are not named here."""
    source = tmp_path / "manager.cpp"
    source.write_text("""
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Manager : public rclcpp::Node
{
public:
  Manager() : Node("manager")
  {
    auto options = rclcpp::NodeOptions().arguments({"--ros-args", "-r", "__node:=manager_client"});
    client_node_ = rclcpp::Node::make_shared("_", options);
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }
  rclcpp::Node::SharedPtr client_node_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Manager>());
  return 0;
}
""")
    found = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert found.rosname == "manager"
    assert found.rosnames == []


def test_a_node_renamed_by_a_list_its_function_fills(tmp_path) -> None:
    """Eloquent's and Foxy's nav2_util::LifecycleNode: the rule is pushed into a local
    list the options are then given (``new_args.push_back(std::string("__node:=") +
    this->get_name() + "_rclcpp_node")``). The helper node was a second node of every
    nav2 server's process: with the launch file's ``name=`` a false duplicate name, and
    without it the server named ``?`` (two nodes, which one is the launch's)."""
    source = tmp_path / "server.cpp"
    source.write_text("""
#include <memory>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Server : public rclcpp::Node
{
public:
  Server(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : Node("controller_server", "", options)
  {
    std::vector<std::string> new_args = options.arguments();
    new_args.push_back("--ros-args");
    new_args.push_back("-r");
    new_args.push_back(std::string("__node:=") + this->get_name() + "_rclcpp_node");
    new_args.push_back("--");
    helper_ = std::make_shared<rclcpp::Node>(
      "_", "", rclcpp::NodeOptions(options).arguments(new_args));
    declare_parameter("controller_frequency", 20.0);
    pub_ = create_publisher<std_msgs::msg::String>("cmd_vel", 10);
  }
  rclcpp::Node::SharedPtr helper_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Server>());
  return 0;
}
""")
    found = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert found.rosname == "controller_server"
    assert found.rosnames == []
    assert {(c.kind, c.name, c.node_name) for c in found.calls} == {
        ("declare", "controller_frequency", None), ("publish", "cmd_vel", None)}



# the ament_cmake package ``pkg`` of the tests below that write their own sources
PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>pkg</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>rclcpp</depend><export><build_type>ament_cmake"
           "</build_type></export></package>\n")


LIBRARY = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace plan {
class Client {
public:
  Client() { node_ = rclcpp::Node::make_shared("domain_client"); }
  rclcpp::Node::SharedPtr node_;
};
class Executor : public rclcpp::Node {
public:
  Executor() : Node("executor") { client_ = std::make_shared<Client>(); }
  std::shared_ptr<Client> client_;
};
class ExecutorClient {
public:
  ExecutorClient() { node_ = rclcpp::Node::make_shared("executor_client"); }
  rclcpp::Node::SharedPtr node_;
};
class Base : public rclcpp::Node {
public:
  Base() : Node("base") {
    pub_ = create_publisher<std_msgs::msg::String>("state", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Derived : public Base {};
class Planner : public rclcpp::Node {
public:
  Planner() : Node("planner") { client_ = std::make_shared<Client>(); }
  std::shared_ptr<Client> client_;
  std::shared_ptr<Derived> derived_ = std::make_shared<Derived>();
};
}  // namespace plan
"""


def test_only_the_nodes_the_executable_makes_name_its_process(write_tree) -> None:
    """plansys2's compute_bt links the executor library, whose ExecutorNode and
    ExecutorClient name nodes "executor" and "executor_client", and builds neither: the
    process's nodes were every name of every file (28 false duplicate-node-names errors,
    domain_expert_node first named after a client it never builds). Now the names of
    the classes main() constructs, transitively, and their bases (an implicit base
    constructor names the node too)."""
    root = write_tree({
        "pkg/package.xml": PACKAGE,
        "pkg/include/pkg/lib.hpp": LIBRARY,
        "pkg/src/lib.cpp": '#include "pkg/lib.hpp"\n',
        "pkg/src/executor_main.cpp": '#include "pkg/lib.hpp"\nint main(int argc, char ** argv)'
                                     " {\n  rclcpp::init(argc, argv);\n"
                                     "  auto node = std::make_shared<plan::Executor>();\n"
                                     "  rclcpp::spin(node);\n}\n",
        "pkg/src/base_main.cpp": '#include "pkg/lib.hpp"\nint main(int argc, char ** argv)'
                                 " {\n  rclcpp::init(argc, argv);\n"
                                 "  rclcpp::spin(std::make_shared<plan::Base>());\n}\n",
        "pkg/src/planner_main.cpp": '#include "pkg/lib.hpp"\nint main(int argc, char ** argv)'
                                    " {\n  rclcpp::init(argc, argv);\n"
                                    "  auto node = std::make_shared<plan::Planner>();\n"
                                    "  rclcpp::spin(node);\n}\n",
    })
    workspace = scan([str(root)])
    executor = extract_cpp([str(root / "pkg/src/lib.cpp"),
                            str(root / "pkg/src/executor_main.cpp")], workspace, cache_dir=None)
    assert executor.rosnames == ["domain_client", "executor"]
    planner = extract_cpp([str(root / "pkg/src/planner_main.cpp"),
                           str(root / "pkg/src/lib.cpp")], workspace, cache_dir=None)
    assert sorted(planner.rosnames) == ["base", "domain_client", "planner"]
    # one node: named by the class main builds, not by the first name of the library
    # (plansys2's domain_expert_node was "domain_expert_client")
    single = extract_cpp([str(root / "pkg/src/base_main.cpp"), str(root / "pkg/src/lib.cpp")],
                         workspace, cache_dir=None)
    assert (single.rosname, single.rosnames) == ("base", [])
    # without a main (a component library), every name stays
    library = extract_cpp([str(root / "pkg/src/lib.cpp")], workspace, cache_dir=None)
    assert sorted(library.rosnames) == ["base", "domain_client", "executor",
                                        "executor_client", "planner"]


UNBUILT = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace plan {
class Executor : public rclcpp::Node {
public:
  Executor() : Node("executor") {
    pub_ = create_publisher<std_msgs::msg::String>("plan", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Monitor : public rclcpp::Node {
public:
  Monitor() : Node("monitor") {
    sub_ = create_subscription<std_msgs::msg::String>("plan", 10, &Monitor::cb);
  }
  static void cb(const std_msgs::msg::String::SharedPtr) {}
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
}  // namespace plan
"""


def test_the_calls_of_a_node_class_main_never_builds_are_not_the_process_s(
        write_tree) -> None:
    """plansys2's domain_expert_node links DomainExpertClient, a class that makes a node
    of its own, and never builds it: the client's 14 calls were given to the process's
    node. A node class the executable's main() never builds makes no call there; with
    a main() that loads plugins by name, its calls stay when a package declares the
    class for a loader (its plugin description: the loader may build it), and not when
    none does (plansys2's executor_node loads its behaviour-tree builders by name and
    links ComputeBT, whose lifecycle services and 13 parameters it was given: 10 false
    multiple-service-servers and 2 multiple-publishers warnings)."""
    root = write_tree({
        "pkg/package.xml": PACKAGE,
        "pkg/include/pkg/lib.hpp": UNBUILT,
        "pkg/src/lib.cpp": '#include "pkg/lib.hpp"\n',
        "pkg/src/main.cpp": '#include "pkg/lib.hpp"\nint main(int argc, char ** argv)'
                            " {\n  rclcpp::init(argc, argv);\n"
                            "  rclcpp::spin(std::make_shared<plan::Executor>());\n}\n",
        "pkg/src/loader.cpp": '#include "pkg/lib.hpp"\n'
                              "#include <pluginlib/class_loader.hpp>\n"
                              "int main(int argc, char ** argv)"
                              " {\n  rclcpp::init(argc, argv);\n"
                              "  pluginlib::ClassLoader<rclcpp::Node> loader(\"pkg\", "
                              "\"rclcpp::Node\");\n"
                              "  auto extra = loader.createSharedInstance(\"pkg/Monitor\");\n"
                              "  rclcpp::spin(std::make_shared<plan::Executor>());\n}\n",
    })
    workspace = scan([str(root)])
    built = extract_cpp([str(root / "pkg/src/lib.cpp"), str(root / "pkg/src/main.cpp")],
                        workspace, cache_dir=None)
    assert (built.rosname, rows(built)) == ("executor", {("publish", "plan", None)})
    loading = extract_cpp([str(root / "pkg/src/lib.cpp"), str(root / "pkg/src/loader.cpp")],
                          workspace, cache_dir=None)
    assert ("subscribe", "plan") not in {(kind, name) for kind, name, _ in rows(loading)}
    # declared for a loader: a plugin description names it
    (root / "pkg/package.xml").write_text(PACKAGE.replace(
        "</export>", '<pkg plugin="${prefix}/plugins.xml"/></export>'))
    (root / "pkg/plugins.xml").write_text(
        '<library path="monitor"><class type="plan::Monitor" base_class_type="rclcpp::Node">'
        "</class></library>\n")
    workspace = scan([str(root)])
    package = workspace.packages["pkg"]
    read_build_files(package, workspace)
    assert [n.plugin_class for n in package.nodes] == ["plan::Monitor"]
    loading = extract_cpp([str(root / "pkg/src/lib.cpp"), str(root / "pkg/src/loader.cpp")],
                          workspace, cache_dir=None)
    assert ("subscribe", "plan") in {(kind, name) for kind, name, _ in rows(loading)}


FLEET = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace fleet {
class Fleet : public rclcpp::Node {
public:
  Fleet() : Node("fleet") { pub_ = create_publisher<std_msgs::msg::String>("fleet_states", 10); }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Door : public rclcpp::Node {
public:
  Door() : Node("door") { pub_ = create_publisher<std_msgs::msg::String>("door_states", 10); }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
class Lift {
public:
  static std::shared_ptr<rclcpp::Node> make() {
    auto node = rclcpp::Node::make_shared("lift");
    node->create_publisher<std_msgs::msg::String>("lift_states", 10);
    return node;
  }
};
rclcpp::Node::SharedPtr make_fleet();
rclcpp::Node::SharedPtr make_door();
extern rclcpp::Node::SharedPtr g_node;
void announce();
class Reporter {
public:
  explicit Reporter(rclcpp::Node * node) {
    pub_ = node->create_publisher<std_msgs::msg::String>("reports", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
void report(rclcpp::Node * node);
template <class NodeT> int run() {
  rclcpp::spin(std::make_shared<NodeT>());
  return 0;
}
}  // namespace fleet
"""


def test_a_linked_library_runs_only_what_main_reaches(write_tree) -> None:
    """open-rmf's executables link rmf_fleet_adapter's library, whose free functions make
    nodes of their own: every executable had every node of the library that a free
    function makes, and their publishers. A free function runs when main() calls it or
    hands it on, a class when main() constructs it, calls its methods or hands it to a
    template, transitively; code main() never reaches makes no call of the process."""
    root = write_tree({
        "pkg/package.xml": PACKAGE,
        "pkg/include/pkg/fleet.hpp": FLEET,
        "pkg/src/fleet.cpp": '#include "pkg/fleet.hpp"\nnamespace fleet {\n'
                             "rclcpp::Node::SharedPtr make_fleet() "
                             "{ return std::make_shared<Fleet>(); }\n"
                             "rclcpp::Node::SharedPtr make_door() "
                             "{ return std::make_shared<Door>(); }\n"
                             "rclcpp::Node::SharedPtr g_node;\nvoid announce() "
                             "{ g_node->create_publisher<std_msgs::msg::String>"
                             "(\"announce\", 10); }\n"
                             "void report(rclcpp::Node * node) { Reporter r(node); }\n}\n",
        "pkg/src/fleet_main.cpp": '#include "pkg/fleet.hpp"\nint main(int argc, char ** argv)'
                                  " {\n  rclcpp::init(argc, argv);\n"
                                  "  rclcpp::spin(fleet::make_fleet());\n}\n",
        "pkg/src/door_main.cpp": '#include "pkg/fleet.hpp"\nint main(int argc, char ** argv)'
                                 " {\n  rclcpp::init(argc, argv);\n"
                                 "  auto factory = &fleet::make_door;\n"
                                 "  fleet::announce();\n"
                                 "  rclcpp::spin(factory());\n}\n",
        "pkg/src/lift_main.cpp": '#include "pkg/fleet.hpp"\nint main(int argc, char ** argv)'
                                 " {\n  rclcpp::init(argc, argv);\n"
                                 "  auto node = fleet::Lift::make();\n"
                                 "  fleet::report(node.get());\n  rclcpp::spin(node);\n}\n",
        "pkg/src/run_main.cpp": '#include "pkg/fleet.hpp"\nint main(int argc, char ** argv)'
                                " {\n  rclcpp::init(argc, argv);\n"
                                "  return fleet::run<fleet::Fleet>();\n}\n",
    })
    made = {name: (found.rosname, found.rosnames, published(found))
            for name, found in each_main(root, ("fleet", "door", "lift", "run"),
                                         [str(root / "pkg/src/fleet.cpp")]).items()}
    assert made == {"fleet": ("fleet", [], ["fleet_states"]),
                    "door": ("door", [], ["announce", "door_states"]),
                    "lift": ("lift", [], ["lift_states", "reports"]),
                    # a class handed to a function template as its argument
                    "run": ("fleet", [], ["fleet_states"])}


@pytest.mark.parametrize("handed", ['"fleet"', "&make_fleet"])
def test_a_node_handed_on_counts_only_where_the_code_that_hands_it_runs(write_tree,
                                                                         handed: str) -> None:
    """A unit of a linked library that hands a node to code the parse does not read (a
    vendor's class) hides constructions only when the function that hands it on runs:
    rmf_task_ros2's Dispatcher.cpp hands its node to its bidding code, and
    door_supervisor runs only the static initialiser of its schema, yet every free
    function of the library was taken as run (door_supervisor got the fleet adapter's
    nodes and their publishers). Where it runs, the vendor's code builds of the library
    what the statement hands it (a function to call back), no more: a package cannot
    name the code of one that depends on it."""
    root = write_tree({
        "pkg/package.xml": PACKAGE,
        "pkg/include/pkg/fleet.hpp": FLEET,
        "pkg/src/fleet.cpp": '#include "pkg/fleet.hpp"\nnamespace fleet {\n'
                             "rclcpp::Node::SharedPtr make_fleet() "
                             "{ return std::make_shared<Fleet>(); }\n"
                             "rclcpp::Node::SharedPtr make_door() "
                             "{ return std::make_shared<Door>(); }\n"
                             "void report(rclcpp::Node * node) { Reporter r(node); }\n}\n",
        "pkg/src/dispatch.cpp": '#include "pkg/fleet.hpp"\n#include <vendor/bidder.h>\n'
                                "namespace fleet {\nint make_schema() { return 1; }\n"
                                "static const int schema = make_schema();\n"
                                "void bid(rclcpp::Node::SharedPtr node) {\n"
                                f"  vendor::Bidder bidder(node, {handed});\n}}\n}}\n",
        "pkg/src/door_main.cpp": '#include "pkg/fleet.hpp"\nint main(int argc, char ** argv)'
                                 " {\n  rclcpp::init(argc, argv);\n"
                                 "  rclcpp::spin(fleet::make_door());\n}\n",
        "pkg/src/bid_main.cpp": '#include "pkg/fleet.hpp"\nnamespace fleet '
                                "{ void bid(rclcpp::Node::SharedPtr node); }\n"
                                "int main(int argc, char ** argv) {\n"
                                "  rclcpp::init(argc, argv);\n  auto door = fleet::make_door();\n"
                                "  fleet::bid(door);\n  rclcpp::spin(door);\n}\n",
    })
    library = [str(root / "pkg/src/fleet.cpp"), str(root / "pkg/src/dispatch.cpp")]
    made = {name: (found.rosname, published(found))
            for name, found in each_main(root, ("door", "bid"), library).items()}
    assert made["door"] == ("door", ["door_states"])
    # the vendor's code, given the node and a factory of the library, may call it
    assert made["bid"][1] == ["door_states", *(["fleet_states"] if "&" in handed else [])]


AGV = """
#include <memory>
#include <string>
#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

namespace fleet {
template <class T, class... A> T * make_impl(A &&... args) { return new T(args...); }
class AgvNode : public rclcpp::Node {
public:
  static std::shared_ptr<AgvNode> make(const std::string & name);
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
private:
  explicit AgvNode(const std::string & name) : Node(name) {}
};
class Dispatcher {
public:
  static std::shared_ptr<Dispatcher> make(rclcpp::Node * node);
  class Implementation;
  Implementation * pimpl_ = nullptr;
};
std::shared_ptr<AgvNode> make_adapter();
class Supervisor : public rclcpp::Node {
public:
  Supervisor() : Node("supervisor") {
    pub_ = create_publisher<std_msgs::msg::String>("supervisor_states", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace fleet
"""


@pytest.mark.parametrize("made_line", [
    # a template of the library, then a call of the implementation's method
    "  made->pimpl_ = make_impl<Implementation>(node);\n  made->pimpl_->start();\n",
    # one of a package the parse does not have (an error names the class), and the
    # implementation's constructor makes the call
    "  made->pimpl_ = rmf_utils::make_impl<Implementation>(node);\n",
])
def test_a_class_only_unreached_code_makes_or_calls_makes_no_call(write_tree,
                                                                    made_line: str) -> None:
    """A class of a linked library that the library's own code makes (its factory
    method constructs it: open-rmf's ``agv::Node::make``) or calls (a private
    implementation, made through a template, of a package the parse may not have:
    ``rmf_task_ros2::Dispatcher``'s) runs only
    where that code runs: door_supervisor links rmf_fleet_adapter's library and was given
    the fleet adapter's publishers. A class nothing constructs or calls keeps its calls
    (a host may run it)."""
    root = write_tree({
        "pkg/package.xml": PACKAGE,
        "pkg/include/pkg/agv.hpp": AGV,
        "pkg/src/agv.cpp": '#include "pkg/agv.hpp"\nnamespace fleet {\n'
                           "std::shared_ptr<AgvNode> AgvNode::make("
                           "const std::string & name) {\n"
                           "  auto node = std::shared_ptr<AgvNode>(new AgvNode(name));\n"
                           "  node->pub_ = node->create_publisher<std_msgs::msg::String>"
                           '("door_requests", 10);\n  return node;\n}\n'
                           "std::shared_ptr<AgvNode> make_adapter() "
                           '{ return AgvNode::make("agv"); }\n'
                           "}\n",
        "pkg/src/dispatcher.cpp": '#include "pkg/agv.hpp"\nnamespace fleet {\n'
                                  "class Dispatcher::Implementation {\npublic:\n"
                                  "  explicit Implementation(rclcpp::Node * node) "
                                  ": node_(node) " + ("{}\n" if "start" in made_line
                                                      else "{ start(); }\n")
                                  + "  void start() { pub_ = node_->create_publisher<"
                                  'std_msgs::msg::String>("dispatch_states", 10); }\n'
                                  "  rclcpp::Node * node_;\n"
                                  "  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr "
                                  "pub_;\n};\n"
                                  "std::shared_ptr<Dispatcher> Dispatcher::make("
                                  "rclcpp::Node * node) {\n"
                                  "  auto made = std::shared_ptr<Dispatcher>(new Dispatcher());\n"
                                  + made_line + "  return made;\n}\n}\n",
        "pkg/src/supervisor_main.cpp": '#include "pkg/agv.hpp"\n'
                                       "int main(int argc, char ** argv) {\n"
                                       "  rclcpp::init(argc, argv);\n"
                                       "  rclcpp::spin("
                                       "std::make_shared<fleet::Supervisor>());\n}\n",
        "pkg/src/adapter_main.cpp": '#include "pkg/agv.hpp"\n'
                                    "int main(int argc, char ** argv) {\n"
                                    "  rclcpp::init(argc, argv);\n"
                                    "  auto node = fleet::make_adapter();\n"
                                    "  auto dispatcher = fleet::Dispatcher::make(node.get());\n"
                                    "  rclcpp::spin(node);\n}\n",
    })
    library = [str(root / "pkg/src/agv.cpp"), str(root / "pkg/src/dispatcher.cpp")]
    made = {name: published(found)
            for name, found in each_main(root, ("supervisor", "adapter"), library).items()}
    assert made["supervisor"] == ["supervisor_states"]
    # (the node given to code the parse does not have, with the class to make: that
    # code builds no node of the library's that the statement does not name)
    assert made["adapter"] == ["dispatch_states", "door_requests"]


def _manifest(name: str, depends: str = "") -> str:
    """PACKAGE named ``name``, depending on ``depends`` too."""
    also = f"<depend>{depends}</depend>" if depends else ""
    return PACKAGE.replace("<name>pkg</name>", f"<name>{name}</name>").replace(
        "<depend>rclcpp</depend>", f"<depend>rclcpp</depend>{also}")


NEGOTIATION_HPP = """
#include "rclcpp/rclcpp.hpp"
namespace traffic {
class Negotiation {
public:
  explicit Negotiation(rclcpp::Node & node);
  class Implementation;
  Implementation * pimpl_ = nullptr;
};
}  // namespace traffic
"""

# a private implementation made through a template of a package the parse does not have
# (rmf_utils' impl_ptr.hpp), in a constructor that calls the API (so its unit is parsed
# again with the names it lacks declared: the call is then no error)
IMPLEMENTED = """
#include "std_msgs/msg/string.hpp"
#include <rmf_utils/impl_ptr.hpp>
namespace {space} {{
class {cls}::Implementation {{
public:
  // an error the names declared do not mend: it may hide what this method builds
  struct Responder {{
    void respond() {{ auto kind = Implementation::missing_kind; (void)kind; }}
  }};
  explicit Implementation({node} node) {{
    pub_ = node{arrow}create_publisher<std_msgs::msg::String>("{topic}", 10);
    Responder().respond();
  }}
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
}};
{made}
}}
"""

DISPATCHER_HPP = """
#include <memory>
#include "rclcpp/rclcpp.hpp"
namespace fleet {
class Dispatcher {
public:
  static std::shared_ptr<Dispatcher> make(rclcpp::Node::SharedPtr node);
  class Implementation;
  Implementation * pimpl_ = nullptr;
};
}  // namespace fleet
"""


@pytest.mark.parametrize("negotiation_read", [True, False])
def test_a_node_handed_to_a_vendor_template_may_build_only_what_it_is_given(
        write_tree, negotiation_read: bool) -> None:
    """Open-RMF's read_only fleet adapter builds rmf_traffic_ros2's Negotiation with its
    node, whose constructor gives it to rmf_utils' make_unique_impl<Implementation> (a
    header the parse does not have): the node handed to code not read made every class
    of every library the adapter links possible, so it was also credited with
    rmf_task_ros2's Dispatcher's /dispatch_states, a class only the dispatcher node
    builds. Code the parse does not have is another package's, which can build nothing
    of the packages that depend on it but what the statement hands it (its template
    argument): the Negotiation's implementation runs, the Dispatcher's does not. Nor
    does the parse error in the Negotiation's implementation, which writes
    ``Implementation`` for its own class, hide a construction of the Dispatcher's (C++
    looks the name up from the class and namespaces around it). Where the Negotiation's
    own code is not among the executable's sources, what it does with the node stays
    unknown, and so anything it may build."""
    made = ("Negotiation::Negotiation(rclcpp::Node & node)\n"
            ": pimpl_(rmf_utils::make_impl<Implementation>(node)) {\n"
            '  node.declare_parameter("negotiation_timeout", 1.0);\n}')
    factory = ("std::shared_ptr<Dispatcher> Dispatcher::make(rclcpp::Node::SharedPtr node) {\n"
               "  auto made = std::make_shared<Dispatcher>();\n"
               "  made->pimpl_ = rmf_utils::make_impl<Implementation>(node);\n"
               '  node->declare_parameter("bidding_time", 2.0);\n  return made;\n}')
    root = write_tree({
        "traffic/package.xml": _manifest("traffic"),
        "traffic/include/traffic/negotiation.hpp": NEGOTIATION_HPP,
        "traffic/src/negotiation.cpp": '#include "traffic/negotiation.hpp"\n'
        + IMPLEMENTED.format(space="traffic", cls="Negotiation", node="rclcpp::Node &",
                             arrow=".", topic="negotiation_notice", made=made),
        "pkg/package.xml": _manifest("pkg", "traffic"),
        "pkg/include/pkg/dispatcher.hpp": DISPATCHER_HPP,
        "pkg/src/dispatcher.cpp": '#include "pkg/dispatcher.hpp"\n'
        + IMPLEMENTED.format(space="fleet", cls="Dispatcher", node="rclcpp::Node::SharedPtr",
                             arrow="->", topic="dispatch_states", made=factory),
        "pkg/src/adapter_main.cpp": '#include "pkg/dispatcher.hpp"\n'
                                    '#include "traffic/negotiation.hpp"\n'
                                    '#include "std_msgs/msg/string.hpp"\n'
                                    "int main(int argc, char ** argv) {\n"
                                    "  rclcpp::init(argc, argv);\n"
                                    '  auto node = rclcpp::Node::make_shared("adapter");\n'
                                    "  auto pub = node->create_publisher<"
                                    'std_msgs::msg::String>("fleet_states", 10);\n'
                                    "  traffic::Negotiation negotiation(*node);\n"
                                    "  rclcpp::spin(node);\n}\n",
    })
    sources = [root / "pkg/src/adapter_main.cpp", root / "pkg/src/dispatcher.cpp",
               *([root / "traffic/src/negotiation.cpp"] if negotiation_read else [])]
    found = extract_cpp([str(p) for p in sources], scan([str(root)]), cache_dir=None)
    assert {d.code for d in found.diagnostics} >= {"CPP_NODE_TO_UNKNOWN", "CPP_NODE_PASSED"}
    assert published(found) == (["fleet_states", "negotiation_notice"] if negotiation_read
                                else ["dispatch_states", "fleet_states"])
