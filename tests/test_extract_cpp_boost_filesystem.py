"""Boost.Filesystem in the stand-ins: bwi_common's scavenger writes
``boost::filesystem::path tmp_path(directory); boost::filesystem::create_directory(
tmp_path);`` in the thread that publishes its results. Without the library's names the
parse declared them permissively, ``create_directory`` as a type, and the second
statement as a redefinition of ``tmp_path``: a clang error in a function that calls the
ROS API, and the node partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <boost/filesystem.hpp>
#include <boost/filesystem/fstream.hpp>
int main(int argc, char** argv) {
  ros::init(argc, argv, "saver");
  ros::NodeHandle nh;
  std::string directory = "/tmp/out";
  if (boost::filesystem::is_directory(directory) == false) {
    boost::filesystem::path tmp_path(directory);
    boost::filesystem::create_directory(tmp_path);
  }
  boost::filesystem::path file = boost::filesystem::path(directory) / "log.txt";
  boost::filesystem::ofstream out(file);
  out << file.string();
  ros::Publisher pub = nh.advertise<std_msgs::String>("saved", 1);
  ros::spin();
}
"""


def test_boost_filesystem_parses(tmp_path) -> None:
    (tmp_path / "saver.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "saver.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "saved")]
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED")] == []
