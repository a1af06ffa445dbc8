"""The standard library's streams and manipulators written unqualified in a class's
method (``cerr``, ``endl``, ``boolalpha``), brought by a ``using namespace std;`` of a
header the parse lacks, are std's. ORB_SLAM3_ROS2 (00c5433) writes ``ss >> boolalpha >>
doRectify;`` and ``cerr << ... << endl;`` in its nodes' constructors, ORB_SLAM3's headers
missing: an unqualified value in a method was never declared (it may be a member of a
base the parse lacks, which a declaration would shadow), so the three stayed errors in
the constructor that makes the node's subscriptions. A ``using std::cerr;`` at namespace
scope shadows no member: a class's own and its bases' are found first."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "System.h"
class SlamNode : public rclcpp::Node {
 public:
  SlamNode(const string &rectify) : Node("slam") {
    stringstream ss(rectify);
    ss >> boolalpha >> do_rectify_;
    if (do_rectify_) { cerr << "rectifying" << endl; }
    sub_ = create_subscription<sensor_msgs::msg::Image>(
        "camera/left", 10, std::bind(&SlamNode::grab, this, std::placeholders::_1));
  }
  void grab(const sensor_msgs::msg::Image::SharedPtr msg) { (void)msg; }
  bool do_rectify_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr sub_;
};
int main(int argc, char **argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SlamNode>("true"));
}
"""


def test_std_streams_unqualified_in_a_method(write_tree) -> None:
    root = write_tree({"p/package.xml": package_xml("p", build_type="ament_cmake"),
                       "p/src/node.cpp": NODE})
    result = extract_cpp([str(root / "p" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls if c.kind == "subscribe"] == [
        ("subscribe", "camera/left")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_PARSE_ERROR" not in codes and "CPP_ERROR_NEAR_CALL" not in codes
    declared = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert not any(n in m for m in declared for n in ("cerr", "endl", "boolalpha"))


def test_a_member_of_the_same_name_is_the_class_s(write_tree) -> None:
    # a class whose base the parse lacks may read a member named like a stream: the
    # namespace-scope using does not take it (the class's own member is found first)
    source = NODE.replace("bool do_rectify_;", "bool do_rectify_; int cerr;").replace(
        'cerr << "rectifying" << endl;', "cerr = 1;")
    root = write_tree({"p/package.xml": package_xml("p", build_type="ament_cmake"),
                       "p/src/node.cpp": source})
    result = extract_cpp([str(root / "p" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert "CPP_PARSE_ERROR" not in [d.code for d in result.diagnostics]
