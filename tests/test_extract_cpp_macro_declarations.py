"""Two variables a macro's expansion declares are two variables. clang places every
declaration of an expansion at the expansion's start, and the extractor told local
variables by file and offset: ros_deep_learning's ``ROS_CREATE_NODE(name)`` declares
``ros::NodeHandle nh;`` and ``ros::NodeHandle private_nh("~");``, which were one
variable written twice, so its handle was known only until the first call it was passed
to by reference (``__ros_declare_parameter(private_nh, name, value)``, which only reads
through it): about 90 names ``?/model_path`` and the like after it."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
#define CREATE_NODE(name) \\
    ros::init(argc, argv, name); \\
    ros::NodeHandle nh; \\
    ros::NodeHandle private_nh("~");
template<typename T> static void declare(ros::NodeHandle& nh, const std::string& name,
                                         const T& value)
{
  if (!nh.hasParam(name))
    nh.setParam(name, value);
}
#define DECLARE(name, v) declare(private_nh, name, v)
int main(int argc, char** argv)
{
  CREATE_NODE("n");
  std::string model = "m";
  float threshold = 0.5f;
  DECLARE("model", model);
  DECLARE("threshold", threshold);
  private_nh.getParam("model", model);
  ros::Publisher p = private_nh.advertise<std_msgs::String>("out", 1);
  ros::Publisher q = nh.advertise<std_msgs::String>("public", 1);
  ros::spin();
}
"""


def test_two_handles_one_macro_declares(write_tree) -> None:
    root = write_tree({"pkg/package.xml": package_xml("pkg"), "pkg/src/node.cpp": NODE})
    result = extract_cpp([str(root / "pkg" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "public"), ("publish", "~out"), ("read", "~model"), ("read", "~model"),
        ("read", "~threshold"), ("write", "~model"), ("write", "~threshold")]
