"""Headers that include each other through relative paths (RxCpp's
``schedulers/rx-currentthread.hpp`` includes ``"../rx-includes.hpp"``, which includes it
back) are each scanned once: the path a quoted include reaches a file by is the file's
own, not one that grows with every turn of the cycle."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "rx/all.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  auto pub = node->create_publisher<std_msgs::msg::String>("chatter", 10);
  return 0;
}
"""


def test_headers_including_each_other_by_relative_paths_are_read_once(write_tree) -> None:
    root = write_tree({
        "talker/package.xml": package_xml("talker", "ament_cmake"),
        "talker/src/main.cpp": NODE,
        # all.hpp -> parts/part.hpp -> ../all.hpp (guarded, as RxCpp's are)
        "talker/src/rx/all.hpp": '#pragma once\n#include "parts/part.hpp"\n',
        "talker/src/rx/parts/part.hpp": '#pragma once\n#include "../all.hpp"\n'
                                        'inline int part() { return 1; }\n',
    })
    main = root / "talker" / "src" / "main.cpp"
    result = extract_cpp([str(main)], scan([str(root)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "chatter")]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
