"""A precompiled prelude that libclang cannot read (removed from the temporary folder by
a cleaner while the run goes on, cut short by a full disk) fails every parse that names
it with ``Error parsing translation unit``: the units of a long run after that moment
were ``CPP_PARSE_FAILED``, their nodes without calls, a different set in each run. The
parse is made again with the prelude's header, and a file gone is precompiled again."""

from __future__ import annotations

import os

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, headers
from haros_arch.workspace import scan

NODE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("talker");
  auto pub = node->create_publisher<std_msgs::msg::String>("chatter", 10);
  rclcpp::spin(node);
}
"""


def _extract(root):
    result = extract_cpp([str(root / "p" / "src" / "talker.cpp")],
                         scan([str(root)], {"ROS_VERSION": "2"}), cache_dir=None,
                         distro="humble")
    return ([d.code for d in result.diagnostics if d.code == "CPP_PARSE_FAILED"],
            [(c.kind, c.name, c.type) for c in result.calls])


def _made() -> list[str]:
    return [p for p in headers._PCH.values() if p is not None]


@pytest.mark.parametrize("damage", ["removed", "cut short"])
def test_a_unit_parses_when_its_precompiled_prelude_is_unreadable(
        write_tree, damage: str) -> None:
    root = write_tree({
        "p/package.xml": package_xml("p", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "p/src/talker.cpp": NODE})
    expected = ([], [("publish", "chatter", "std_msgs/msg/String")])
    headers._PCH.clear()  # only this unit's prelude (other tests' are made again if used)
    assert _extract(root) == expected
    assert _made()
    for path in _made():
        if damage == "removed":
            os.remove(path)
        else:
            with open(path, "r+b") as handle:
                handle.truncate(os.path.getsize(path) // 2)
    assert _extract(root) == expected
    assert _extract(root) == expected  # the next unit's prelude: made again, readable
    assert all(os.path.getsize(p) > 0 for p in _made())
