"""roscpp's version macros (ros/common.h): code that tests the version in ``#if``
(``ROS_VERSION_MINIMUM(1, 13, 1)``, web_video_server, franka_gazebo, move_base_flex)
takes the branch a noetic build takes, instead of a preprocessor error that drops it
and leaves the function partial."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <std_msgs/String.h>
int main(int argc, char ** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
#if ROS_VERSION_MINIMUM(1, 13, 1)
  ros::Publisher p = nh.advertise<std_msgs::String>("new", 1);
#else
  ros::Publisher p = nh.advertise<std_msgs::String>("old", 1);
#endif
#if ROS_VERSION_GE(ROS_VERSION_MAJOR, ROS_VERSION_MINOR, 0, 1, 17, 0)
  ros::Publisher q = nh.advertise<std_msgs::String>("future", 1);
#endif
#if ROS_VERSION >= ROS_VERSION_COMBINED(1, 0, 0)
  ros::Publisher r = nh.advertise<std_msgs::String>("one", 1);
#endif
}
"""


@pytest.mark.parametrize("header", ["ros/ros.h", "ros/common.h", "ros/node_handle.h"])
def test_roscpp_version_macros(tmp_path, header: str) -> None:
    (tmp_path / "package.xml").write_text(package_xml("talk").replace(
        "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"))
    source = tmp_path / "talker.cpp"
    source.write_text(SOURCE.replace("ros/ros.h", header))
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [c.name for c in result.calls if c.kind == "publish"] == ["new", "one"]
    assert not [d for d in result.diagnostics
                if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    # with no distribution known, kinetic's parse reads the #else: each under its branch
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.name, [str(k) for k in c.conditions]) for c in result.calls
            if c.kind == "publish"] == [
        ("new", ["#if (ROS_VERSION_MINIMUM(1, 13, 1))"]),
        ("old", ["#else (ROS_VERSION_MINIMUM(1, 13, 1))"]), ("one", [])]


@pytest.mark.skipif(not os.path.isfile("/usr/include/ros/common.h"),
                    reason="needs Debian's libroscpp-dev as the oracle")
def test_the_stand_in_defines_what_debians_roscpp_defines() -> None:
    """The same macros as the real header (the numbers are the analysed distribution's,
    extract/cpp/versions.py: Debian ships a snapshot older than noetic's last release)."""
    import re

    def defined(text: str) -> set[str]:
        return set(re.findall(r"^\s*#\s*define\s+(ROS_VERSION\w*)", text, re.MULTILINE))

    real = Path("/usr/include/ros/common.h").read_text()
    ours = (Path(__file__).resolve().parent.parent / "haros_arch" / "extract" / "standin" /
            "ros" / "common.h").read_text()
    assert defined(real) and defined(real) <= defined(ours)
