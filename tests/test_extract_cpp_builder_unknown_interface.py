"""rosidl's builders (``pkg::build<T>()``) were declared only for interfaces whose fields
the catalogue or the workspace tells; a message known only by name (its package not
here) had none, so ``acme_msgs::build<acme_msgs::msg::Pose>().position(p)`` was an error
and the calls of the function beside it were said near an error (thirty-third session,
Autoware); where another interface of its package is known, ``build`` is declared for
those and ``build<Pose>()`` is an error beside the calls. Now such a message's builder
is the message itself, whose fields the parse takes as it takes any unknown message's
(``msg.position``, CPP_MESSAGE_FIELD)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <acme_msgs/msg/point.hpp>
#include <acme_msgs/msg/pose.hpp>
#include <acme_msgs/srv/move.hpp>
class Node : public rclcpp::Node {
public:
  Node() : rclcpp::Node("node") {
    const auto point = acme_msgs::build<acme_msgs::msg::Point>().x(1.0).y(2.0);
    const auto pose = acme_msgs::build<acme_msgs::msg::Pose>().x(1.0).y(2.0).frame("map");
    const auto request = acme_msgs::build<acme_msgs::srv::Move_Request>().target(pose);
    out_ = create_publisher<std_msgs::msg::String>("out", 1);
    poses_ = create_publisher<acme_msgs::msg::Pose>("pose", 1);
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr out_;
  rclcpp::Publisher<acme_msgs::msg::Pose>::SharedPtr poses_;
};
"""


def _extract(root):
    result = extract_cpp([str(root / "node" / "node.cpp")], scan([str(root)]),
                         cache_dir=None, distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NODE_PARTIAL")] == []
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("publish", "out", "std_msgs/msg/String"),
        ("publish", "pose", "acme_msgs/msg/Pose")]
    return result


def test_the_builder_of_a_message_known_by_name(tmp_path) -> None:
    """acme_msgs has Point here, not Pose: ``build`` is declared, by Point's header, and
    ``build<Pose>()`` was a function used before it is defined, beside the calls."""
    (tmp_path / "node").mkdir()
    (tmp_path / "acme_msgs" / "msg").mkdir(parents=True)
    (tmp_path / "node" / "package.xml").write_text(package_xml("node", "ament_cmake"))
    (tmp_path / "acme_msgs" / "package.xml").write_text(
        package_xml("acme_msgs", "ament_cmake"))
    (tmp_path / "acme_msgs" / "msg" / "Point.msg").write_text("float64 x\nfloat64 y\n")
    (tmp_path / "node" / "node.cpp").write_text(NODE)
    result = _extract(tmp_path)
    # the fields of the chain, as of any message known by name: said, not an error
    assert sorted(d.location.line for d in result.diagnostics
                  if d.code == "CPP_MESSAGE_FIELD") == [11, 12]


def test_the_builder_of_a_package_not_here(tmp_path) -> None:
    """No acme_msgs at all: each header synthesised without fields, with its builder
    (before, ``acme_msgs::build`` was a name the parse declared permissively, after a
    parse with six errors)."""
    (tmp_path / "node").mkdir()
    (tmp_path / "node" / "package.xml").write_text(package_xml("node", "ament_cmake"))
    (tmp_path / "node" / "node.cpp").write_text(NODE)
    result = _extract(tmp_path)
    assert [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"] == []
