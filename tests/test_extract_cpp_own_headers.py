"""A package whose headers our stand-ins also provide (rclcpp_components, image_transport,
...) is extracted against its own headers: a header of its include folder wins over the
umbrella stand-in, while the stand-in files themselves keep their place."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

MANAGER = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace rclcpp_components {
class ComponentManager : public rclcpp::Node {
public:
  ComponentManager() : rclcpp::Node("component_manager") {
    pub_ = create_publisher<std_msgs::msg::String>("loaded", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}
"""

MAIN = """
#include <memory>
#include "rclcpp_components/component_manager.hpp"
int main() {
  auto node = std::make_shared<rclcpp_components::ComponentManager>();
  return 0;
}
"""


def _workspace(write_tree, package: str, nested: bool = False):
    include = f"{package}/include/{package}/" + (f"{package}/" if nested else "")
    root = write_tree({
        f"{package}/package.xml": package_xml(package, "ament_cmake"),
        include + "component_manager.hpp": MANAGER,
        f"{package}/src/container.cpp": MAIN,
    })
    return root, root / package / "src" / "container.cpp"


def test_own_header_wins_over_the_umbrella_stand_in(write_tree) -> None:
    root, main = _workspace(write_tree, "rclcpp_components")
    result = extract_cpp([str(main)], scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "loaded")]


def test_own_header_in_the_nested_ros2_layout(write_tree) -> None:
    root, main = _workspace(write_tree, "rclcpp_components", nested=True)
    result = extract_cpp([str(main)], scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "loaded")]



def test_a_package_whose_api_the_extractor_knows_keeps_the_stand_ins_first(write_tree) -> None:
    from haros_arch.extract.cpp.headers import IncludeSetup

    root = write_tree({
        "tf2_ros/package.xml": package_xml("tf2_ros"),
        "tf2_ros/include/tf2_ros/transform_listener.h": "namespace tf2_ros {}\n",
        "tf2_ros/src/echo.cpp": "int main() { return 0; }\n",
        "rclcpp_components/package.xml": package_xml("rclcpp_components"),
        "rclcpp_components/include/rclcpp_components/component_manager.hpp": MANAGER,
        "rclcpp_components/src/container.cpp": MAIN,
    })
    echo = str(root / "tf2_ros" / "src" / "echo.cpp")
    container = str(root / "rclcpp_components" / "src" / "container.cpp")
    setup = IncludeSetup(scan([str(root)]), [], False, sources=[echo, container])
    try:
        own = str(root / "rclcpp_components" / "include")
        assert setup.arguments(False, container)[:2] == ["-I", own]
        assert str(root / "tf2_ros" / "include") not in setup.arguments(False, echo)[:2]
    finally:
        setup.close()


EXPORTED = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "teleop/Teleop_export.h"
namespace teleop {
class TELEOP_EXPORT Teleop : public rclcpp::Node {  // Teleop_export.h is no message
public:
  Teleop() : rclcpp::Node("teleop") {
    pub_ = create_publisher<std_msgs::msg::String>("cmd", 10);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}
int main() {
  auto node = std::make_shared<teleop::Teleop>();
  return 0;
}
"""


def test_a_generated_export_header_defines_its_macros(write_tree) -> None:
    root = write_tree({
        "teleop/package.xml": package_xml("teleop", "ament_cmake"),
        "teleop/src/teleop.cpp": EXPORTED,
    })
    main = root / "teleop" / "src" / "teleop.cpp"
    result = extract_cpp([str(main)], scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "cmd")]
    assert not [d for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"]


CPP_HOLDER = """
#include <rclcpp/rclcpp.hpp>
namespace lib {
class Holder { public: const rclcpp::Node::SharedPtr& getNode() const; };
}
"""

CPP_USER = """
#include <algorithm>
#include <set>
#include <string>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <lib/holder.hpp>
void configure(const lib::Holder& holder, const std::vector<std::string>& more) {
  std::set<std::string> names;
  names.insert(more.begin(), more.end());
  std::vector<std::string> sorted(more);
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::string ns = holder.getNode()->get_effective_namespace() + ".x";
  bool allow;
  holder.getNode()->get_parameter_or("allow", allow, true);
}
"""


def test_headers_of_a_library_folder_of_another_package_are_found(write_tree) -> None:
    # MoveIt's layout: moveit_ros_planning keeps each library's headers in
    # <package>/<library>/include (moveit_cpp/include/moveit/moveit_cpp/moveit_cpp.hpp)
    root = write_tree({
        "lib/package.xml": package_xml("lib", "ament_cmake"),
        "lib/holder/include/lib/holder.hpp": CPP_HOLDER,
        "user/package.xml": package_xml("user", "ament_cmake"),
        "user/src/user.cpp": CPP_USER,
    })
    result = extract_cpp([str(root / "user" / "src" / "user.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name, c.default) for c in result.calls] == [("read", "allow", True)]
    assert not [d for d in result.diagnostics
                if d.code in ("CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR")]


def test_headers_beside_the_sources_included_from_the_package_root(write_tree) -> None:
    """cartographer_ros keeps ``node.h`` beside ``node.cc`` in ``cartographer_ros/`` and
    includes it as ``"cartographer_ros/node.h"`` from the package root (its CMakeLists'
    ``${PROJECT_SOURCE_DIR}``): the header was not found, ``Node`` undeclared and the
    node's 13 advertise calls missed."""
    root = write_tree({
        "carto/package.xml": package_xml("carto"),
        "carto/carto/constants.h": 'constexpr int kQueue = 1;\n',
        "carto/carto/node.h": """
            #include <ros/ros.h>
            #include <std_msgs/String.h>
            #include "carto/constants.h"
            namespace carto {
            class Node {
             public:
              Node();
             private:
              ros::NodeHandle node_handle_;
              ros::Publisher pub_;
            };
            }
            """,
        "carto/carto/node.cc": """
            #include "carto/node.h"
            namespace carto {
            Node::Node() {
              pub_ = node_handle_.advertise<std_msgs::String>("submap_list", kQueue);
            }
            }
            """,
    })
    source = root / "carto" / "carto" / "node.cc"
    result = extract_cpp([str(source)], scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name, c.queue_size) for c in result.calls] == [
        ("publish", "submap_list", 1)]


REPUBLISH_HPP = """
#include <string>
#include "image_transport/image_transport.hpp"
#include "image_transport/visibility_control.hpp"
#include "image_transport/publisher.hpp"
#include <rclcpp/rclcpp.hpp>
namespace image_transport {
class IMAGE_TRANSPORT_PUBLIC Republisher : public rclcpp::Node {
public:
  explicit Republisher(const rclcpp::NodeOptions & options);
private:
  image_transport::Publisher pub_;
};
}
"""

REPUBLISH_CPP = """
#include "image_transport/republish.hpp"
#include <std_msgs/msg/string.hpp>
namespace image_transport {
Republisher::Republisher(const rclcpp::NodeOptions & options)
: Node("image_republisher", options) {
  std::string in_transport = "raw";
  this->declare_parameter<std::string>("in_transport", in_transport);
  pub_ = image_transport::create_publisher(this, "out");
}
}
"""


def test_a_header_of_a_stood_in_package_that_the_stand_in_lacks_is_read(write_tree) -> None:
    """image_transport's own ``republish.hpp`` declares a class (``Republisher``) that no
    stand-in of image_transport has: it was replaced by the umbrella stand-in like the
    package's API headers, ``Republisher`` was undeclared and the node's calls lost."""
    root = write_tree({
        "image_transport/package.xml": package_xml("image_transport", "ament_cmake"),
        "image_transport/include/image_transport/republish.hpp": REPUBLISH_HPP,
        "image_transport/include/image_transport/image_transport.hpp": (
            "namespace image_transport { class ImageTransport { public: int x; }; }\n"),
        "image_transport/include/image_transport/visibility_control.hpp": (
            "#define IMAGE_TRANSPORT_PUBLIC\n"),
        "image_transport/include/image_transport/publisher.hpp": (
            "namespace image_transport {\nclass Publisher\n{ public: int ours; };\n}\n"),
        "image_transport/src/republish.cpp": REPUBLISH_CPP,
    })
    source = root / "image_transport" / "src" / "republish.cpp"
    result = extract_cpp([str(source)], scan([str(root)]), cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "in_transport"), ("publish", "out")]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]


SEND_EVENT_HPP = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
namespace trees {
class SendEvent {
public:
  explicit SendEvent(rclcpp::Node::SharedPtr node);
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}
"""

SEND_EVENT_CPP = """
#include "trees/action/send_event.hpp"
#include "trees/action/dock.hpp"
namespace trees {
SendEvent::SendEvent(rclcpp::Node::SharedPtr node)
{
  pub_ = node->create_publisher<std_msgs::msg::String>("event", 1);
  trees::action::Dock::Goal goal;
  goal.dock_id = "a";
}
}
"""


def test_a_header_at_an_interface_path_that_defines_no_interface_is_read(write_tree) -> None:
    """aerostack2's as2_behavior_tree keeps its tree nodes' headers in
    ``include/as2_behavior_tree/action/``: ``as2_behavior_tree/action/arm_service.hpp``
    looks like the header of an action ``ArmService`` of the package, and an empty one
    was synthesised in its place, though the package defines no such action: every tree
    node's class was undeclared (55 clang errors) and their calls lost. A header the
    package defines (``action/Dock.action``) is still the interface's."""
    root = write_tree({
        "trees/package.xml": package_xml("trees", "ament_cmake"),
        "trees/action/Dock.action": "string dock_id\n---\nbool ok\n---\nfloat32 left\n",
        "trees/include/trees/action/send_event.hpp": SEND_EVENT_HPP,
        "trees/src/send_event.cpp": SEND_EVENT_CPP,
    })
    result = extract_cpp([str(root / "trees" / "src" / "send_event.cpp")],
                         scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "event")]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
