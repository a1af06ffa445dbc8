"""Values given to a node class's constructor (``std::make_shared<T>(args)``, ``new
T(args)``, ``T obj(args)``, in the same file or in another file of the node) flow into
its parameters, its defaults and the members it initialises, so the names built from
them resolve: one call per value the node's files pass."""

from __future__ import annotations

import os

import pytest

from haros_arch.extract.cpp import CppResult, extract_cpp
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "constructors")
SRC = os.path.join(ROOT, "src", "relay2", "src")


def rows(result: CppResult) -> list[tuple[object, ...]]:
    return [(c.kind, c.name, c.type, c.queue_size, c.location.file.rsplit("/", 1)[-1]
             if c.location.file else None, c.location.line) for c in result.calls]


@pytest.fixture(scope="module")
def relays() -> CppResult:
    sources = [os.path.join(SRC, "relays.cpp"), os.path.join(SRC, "relay_node.cpp")]
    return extract_cpp(sources, scan([ROOT]), cache_dir=None)


@pytest.fixture(scope="module")
def camera() -> CppResult:
    return extract_cpp([os.path.join(SRC, "camera.cpp")], scan([ROOT]), cache_dir=None)


def test_constructor_in_another_file(relays: CppResult) -> None:
    """make_shared, new and a local object in relays.cpp; the constructor, which keeps
    the output topic in a member, in relay_node.cpp."""
    assert rows(relays) == [
        ("publish", "chatter_relayed", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("publish", "right", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("publish", "down", "std_msgs/msg/String", 10, "relay_node.cpp", 9),
        ("subscribe", "chatter", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("subscribe", "left", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("subscribe", "up", "std_msgs/msg/String", 10, "relay_node.cpp", 10),
        ("publish", "chatter_relayed/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
        ("publish", "right/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
        ("publish", "down/status", "std_msgs/msg/String", 1, "relay_node.cpp", 16),
    ]
    assert not [d for d in relays.diagnostics if d.code == "CPP_DYNAMIC_NAME"]


def test_node_name_from_several_constructions_is_unknown(relays: CppResult) -> None:
    """Node(name) with "relay" (the default), "second" and "third": no one name."""
    assert relays.rosname == "?"


def test_defaults_of_the_constructor(camera: CppResult) -> None:
    """make_shared<CameraNode>(topic), topic a string variable: passing it on to a
    constructor does not change it."""
    assert rows(camera) == [
        ("publish", "image", "std_msgs/msg/String", 5, "camera.cpp", 14),
        ("publish", "camera_node/info", "std_msgs/msg/String", 1, "camera.cpp", 15),
    ]
    assert camera.rosname == "camera_node"


ROS2_MANIFEST = """<package format="3"><name>twist_relay</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer><license>MIT</license>
<depend>rclcpp</depend><depend>geometry_msgs</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

# turtlebot3_node's TwistSubscriber: a class (not a template) whose constructors are
# templates over the callbacks, built with std::make_unique
TWIST_SUBSCRIBER = """
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>
#include <geometry_msgs/msg/twist_stamped.hpp>

class TwistSubscriber {
public:
  template<typename TwistCallbackT, typename StampedCallbackT>
  TwistSubscriber(const rclcpp::Node::SharedPtr & node, const std::string & topic,
                  const rclcpp::QoS & qos, TwistCallbackT && twist_cb,
                  StampedCallbackT && stamped_cb) {
    if (stamped_) {
      stamped_sub_ = node->create_subscription<geometry_msgs::msg::TwistStamped>(
        topic, qos, std::forward<StampedCallbackT>(stamped_cb));
    } else {
      twist_sub_ = node->create_subscription<geometry_msgs::msg::Twist>(
        topic, qos, std::forward<TwistCallbackT>(twist_cb));
    }
  }
private:
  bool stamped_{false};
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr twist_sub_;
  rclcpp::Subscription<geometry_msgs::msg::TwistStamped>::SharedPtr stamped_sub_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("relay");
  auto sub = std::make_unique<TwistSubscriber>(
    node, "cmd_vel", rclcpp::QoS(10),
    [](const geometry_msgs::msg::Twist::SharedPtr) {},
    [](const geometry_msgs::msg::TwistStamped::SharedPtr) {});
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_constructor_template_built_by_make_unique_names_its_calls(tmp_path) -> None:
    """``std::make_unique<T>(node, "cmd_vel", ...)`` where T's constructor is a template:
    the constructor's ``topic`` is the string the construction passes (it was unknown:
    only a constructor that is not a template was looked for)."""
    (tmp_path / "package.xml").write_text(ROS2_MANIFEST)
    source = tmp_path / "relay.cpp"
    source.write_text(TWIST_SUBSCRIBER)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    found = sorted((c.kind, c.name, c.type) for c in result.calls if c.kind == "subscribe")
    assert found == [("subscribe", "cmd_vel", "geometry_msgs/msg/Twist"),
                     ("subscribe", "cmd_vel", "geometry_msgs/msg/TwistStamped")]


SUBSCRIBER_HEADER = """
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/twist.hpp>

class VelocityInput {
public:
  VelocityInput(const rclcpp::Node::SharedPtr & node, const std::string & topic) {
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(
      topic, 10, [](const geometry_msgs::msg::Twist::SharedPtr) {});
  }
private:
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr sub_;
};
"""

BUILDS_IT = """
#include <memory>
#include "twist_relay/velocity_input.hpp"

std::unique_ptr<VelocityInput> make_input(const rclcpp::Node::SharedPtr & node) {
  return std::make_unique<VelocityInput>(node, "cmd_vel");
}
"""

INCLUDES_IT = """
#include <memory>
#include "twist_relay/velocity_input.hpp"

std::unique_ptr<VelocityInput> make_input(const rclcpp::Node::SharedPtr & node);

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("relay");
  auto input = make_input(node);
  rclcpp::spin(node);
  return 0;
}
"""


def _with_velocity_input(root) -> None:
    """A ROS 2 package at ``root`` with ``SUBSCRIBER_HEADER`` as
    ``twist_relay/velocity_input.hpp``."""
    (root / "include" / "twist_relay").mkdir(parents=True)
    (root / "package.xml").write_text(ROS2_MANIFEST)
    (root / "include" / "twist_relay" / "velocity_input.hpp").write_text(SUBSCRIBER_HEADER)


def test_a_header_constructor_built_in_one_unit_is_named_in_the_others(tmp_path) -> None:
    """The constructor is defined in a header that both units of the node include; one
    unit builds it with "cmd_vel", the other only includes it. The other unit's copy of
    the call is filled with what the first passes (it was a second subscription named
    '?')."""
    _with_velocity_input(tmp_path)
    (tmp_path / "input.cpp").write_text(BUILDS_IT)
    (tmp_path / "main.cpp").write_text(INCLUDES_IT)
    result = extract_cpp([str(tmp_path / "main.cpp"), str(tmp_path / "input.cpp")],
                         scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "cmd_vel", "geometry_msgs/msg/Twist")]


def test_a_header_constructor_no_unit_builds_makes_no_call(tmp_path) -> None:
    """A node whose file includes the header of a class it never constructs (navigation2's
    TwistSubscriber and FootprintSubscriber, included by nodes that build neither):
    the constructor's subscription, named after its parameter, is not the node's. It was
    a subscription named '?'."""
    _with_velocity_input(tmp_path)
    (tmp_path / "main.cpp").write_text(INCLUDES_IT.replace(
        "std::unique_ptr<VelocityInput> make_input(const rclcpp::Node::SharedPtr & node);\n",
        "").replace("  auto input = make_input(node);\n",
                    '  auto pub = node->create_publisher<geometry_msgs::msg::Twist>("out", 1);\n'))
    result = extract_cpp([str(tmp_path / "main.cpp")], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    assert not [d for d in result.diagnostics if d.code == "CPP_DYNAMIC_NAME"]


PLUGIN = """
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
"""


def test_a_method_the_unbuilt_constructor_calls_keeps_its_call(tmp_path) -> None:
    """ROS 1 navigation's TrajectoryPlannerROS: a plugin built by its default
    constructor, whose other constructor calls ``initialize(name)``, the virtual method
    the host calls. Nobody here builds it with a name, but ``initialize`` runs all the same: its
    subscription stays, with the part of the name nobody here gives unknown."""
    (tmp_path / "package.xml").write_text(ROS2_MANIFEST)
    (tmp_path / "planner.cpp").write_text(PLUGIN)
    result = extract_cpp([str(tmp_path / "planner.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "?/cmd")]


def test_a_construction_whose_arguments_are_not_read_still_makes_the_calls(tmp_path) -> None:
    """The unit builds the class with a topic of a type the parse does not know (a
    vendor helper's): nothing is read from the construction, but the class is built, so
    its subscription is the node's, named '?'."""
    _with_velocity_input(tmp_path)
    (tmp_path / "input.cpp").write_text(BUILDS_IT.replace(
        '#include <memory>\n', '#include <memory>\n#include <vendor/topics.hpp>\n').replace(
        '(node, "cmd_vel")', "(node, vendor::Topics::velocity())"))
    (tmp_path / "main.cpp").write_text(INCLUDES_IT)
    result = extract_cpp([str(tmp_path / "main.cpp"), str(tmp_path / "input.cpp")],
                         scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "?", "geometry_msgs/msg/Twist")]


COSTMAP_SUBSCRIBER = """
#pragma once
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class MapInput {
public:
  MapInput(const std::weak_ptr<rclcpp::Node> & parent, const std::string & topic) {
    auto node = parent.lock();
    sub_ = node->create_subscription<std_msgs::msg::String>(
      topic + "_weak", 1, [](const std_msgs::msg::String::SharedPtr) {});
  }
  template<typename NodeT>
  MapInput(const NodeT & parent, const std::string & topic, int depth = 1) {
    sub_ = parent->template create_subscription<std_msgs::msg::String>(
      topic, depth, [](const std_msgs::msg::String::SharedPtr) {});
  }
private:
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
"""

BUILDS_MAP_INPUT = """
#include <memory>
#include "twist_relay/map_input.hpp"

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("mapper");
  auto input = std::make_unique<MapInput>(node, "map");
  std::weak_ptr<rclcpp::Node> weak = node;
  auto other = std::make_unique<MapInput>(weak, "other_map");
  rclcpp::spin(node);
  return 0;
}
"""


def test_make_unique_chooses_the_constructor_that_takes_the_arguments_as_they_are(
        tmp_path) -> None:
    """nav2's CostmapSubscriber: a constructor over a ``WeakPtr`` and a constructor
    template over any node, both taking two arguments. ``make_unique`` with the shared
    pointer builds through the template, with the weak pointer through the other one,
    as C++ chooses; each gives its calls their names (both were unknown: two
    constructors fitted)."""
    (tmp_path / "package.xml").write_text(ROS2_MANIFEST)
    (tmp_path / "include" / "twist_relay").mkdir(parents=True)
    (tmp_path / "include" / "twist_relay" / "map_input.hpp").write_text(COSTMAP_SUBSCRIBER)
    (tmp_path / "main.cpp").write_text(BUILDS_MAP_INPUT)
    result = extract_cpp([str(tmp_path / "main.cpp")], scan([str(tmp_path)]), cache_dir=None)
    assert sorted((c.kind, c.name, c.location.line) for c in result.calls) == [
        ("subscribe", "map", 17), ("subscribe", "other_map_weak", 12)]


def test_an_error_away_from_any_construction_does_not_keep_the_calls(tmp_path) -> None:
    """An error the parse leaves in a function that does not name the class (ROS 1
    navigation's costmap tools: errors in a helper of their library, none near a
    construction of Costmap2DROS) cannot hide a construction of it: the calls of the
    constructor nobody calls are still left out."""
    _with_velocity_input(tmp_path)
    (tmp_path / "main.cpp").write_text(INCLUDES_IT.replace(
        "std::unique_ptr<VelocityInput> make_input(const rclcpp::Node::SharedPtr & node);\n",
        "int helper() { return vendor::count(); }\n").replace(
        "  auto input = make_input(node);\n",
        '  auto pub = node->create_publisher<geometry_msgs::msg::Twist>("out", 1);\n'))
    result = extract_cpp([str(tmp_path / "main.cpp")], scan([str(tmp_path)]), cache_dir=None)
    assert "CPP_PARSE_ERROR" in [d.code for d in result.diagnostics]
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]


@pytest.mark.parametrize("given", ["node", "\"dock\""])
def test_a_class_built_without_its_constructors_code_keeps_the_calls(
        tmp_path, given: str) -> None:
    """opennav_following builds opennav_docking's Controller with its node; the
    Controller's constructor, in opennav_docking's sources (not a file of this node),
    builds a FootprintSubscriber, a member of the Controller. What it builds is not seen
    here, so the subscription of the header's class stays, named '?' (given the node,
    the node is also partial; given a name only, the class's members still say what it
    may build)."""
    manifest = ROS2_MANIFEST.replace("twist_relay", "{name}")
    docking = tmp_path / "src" / "docking"
    (docking / "include" / "docking").mkdir(parents=True)
    (docking / "src").mkdir()
    (docking / "package.xml").write_text(manifest.format(name="docking"))
    (docking / "include" / "docking" / "velocity_input.hpp").write_text(SUBSCRIBER_HEADER)
    (docking / "include" / "docking" / "controller.hpp").write_text(
        "#pragma once\n#include <memory>\n#include \"docking/velocity_input.hpp\"\n"
        "class Controller {\npublic:\n"
        "  explicit Controller(const rclcpp::Node::SharedPtr & node);\n"
        "  explicit Controller(const std::string & name);\n"
        "private:\n  std::unique_ptr<VelocityInput> input_;\n};\n")
    (docking / "src" / "controller.cpp").write_text(
        "#include \"docking/controller.hpp\"\n"
        "Controller::Controller(const rclcpp::Node::SharedPtr & node)\n"
        ": input_(std::make_unique<VelocityInput>(node, \"footprint\")) {}\n")
    following = tmp_path / "src" / "following"
    following.mkdir(parents=True)
    (following / "package.xml").write_text(
        manifest.format(name="following").replace(
            "<depend>rclcpp</depend>", "<depend>rclcpp</depend><depend>docking</depend>"))
    (following / "main.cpp").write_text(
        "#include <memory>\n#include \"docking/controller.hpp\"\n"
        "int main(int argc, char ** argv) {\n  rclcpp::init(argc, argv);\n"
        "  auto node = std::make_shared<rclcpp::Node>(\"following\");\n"
        f"  auto controller = std::make_unique<Controller>({given});\n"
        "  rclcpp::spin(node);\n  return 0;\n}\n")
    result = extract_cpp([str(following / "main.cpp")], scan([str(tmp_path)]),
                         cache_dir=None)
    assert ("CPP_NODE_PASSED" in [d.code for d in result.diagnostics]) == (given == "node")
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "?")]


@pytest.mark.parametrize("calls_it", [True, False])
def test_the_cache_keeps_what_a_unit_says_of_its_constructions(tmp_path,
                                                                calls_it: bool) -> None:
    """The calls' constructor and the unit's unseen words are kept in the cache: a run
    answered from it leaves out and keeps the same calls as the parse. The unit that
    builds the class hands the node to code the parse lacks, so anything may be built
    there where it runs; where ``main()`` never calls it, nothing it builds is in the
    process."""
    root = tmp_path / "ws"
    _with_velocity_input(root)
    main = INCLUDES_IT if calls_it else INCLUDES_IT.replace(
        "std::unique_ptr<VelocityInput> make_input(const rclcpp::Node::SharedPtr & node);\n",
        "").replace("  auto input = make_input(node);\n", "")
    (root / "main.cpp").write_text(main)
    (root / "input.cpp").write_text(BUILDS_IT.replace(
        '#include <memory>\n', '#include <memory>\n#include <vendor/topics.hpp>\n').replace(
        '(node, "cmd_vel")', "(node, vendor::Topics::velocity())"))
    ws = scan([str(root)])
    alone = [str(root / "main.cpp")]
    both = [str(root / "main.cpp"), str(root / "input.cpp")]
    cache_dir = str(tmp_path / "cache")
    for _run in range(2):  # parsed, then answered from the cache
        assert extract_cpp(alone, ws, cache_dir=cache_dir, jobs=1).calls == []
        assert [(c.kind, c.name, c.made_in) for c in extract_cpp(
            both, ws, cache_dir=cache_dir, jobs=1).calls] == (
                [("subscribe", "?", None)] if calls_it else [])
