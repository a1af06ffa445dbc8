"""``std::string::erase`` of one position: Autoware's image_rotator, image_rectifier,
pixel_cloud_fusion and roi_object_filter (core_perception) drop a doubled leading ``/``
of their namespace with ``name_space_str.erase(name_space_str.begin())`` before they
subscribe. The stand-in string had only ``erase(pos, n)`` and ``erase(first, last)``, so
the call was a C++ error in the function that subscribes and each node was partial.
``erase(0)`` (a count, not a null iterator) must still choose the index form."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = r"""
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <string>

void onImage(const std_msgs::String::ConstPtr& msg) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "rotator");
  ros::NodeHandle nh;
  std::string ns = ros::this_node::getNamespace();
  if (ns.substr(0, 2) == "//") {
    ns.erase(ns.begin());
  }
  std::string::iterator last = ns.end() - 1;
  std::string::const_iterator first = ns.cbegin();
  ns.erase(last);
  ns.erase(first);
  std::string copy = ns;
  copy.erase(0);
  copy.erase(1, 2).erase(copy.begin(), copy.end());
  ros::Subscriber sub = nh.subscribe("image_raw", 1, onImage);
  ros::spin();
}
"""


def test_erase_of_one_position_parses(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("rotator"))
    source = tmp_path / "rotator.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [("subscribe", "image_raw")]
