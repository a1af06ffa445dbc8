"""An unqualified call of a function whose header is missing, in a method of a class
that derives from nothing (nor does any class around it), cannot be a member of a
base: it is declared at namespace scope, as in a free function, not only as a friend
of the permissive class, which argument-dependent lookup alone finds. darknet_ros
1027a28's YoloObjectDetector::readParameters calls ``XOpenDisplay(NULL)`` of
<X11/Xlib.h> (not read): the error stayed, "C++ error in readParameters, which calls
the ROS API", and the nodelet was partial for a call that hides none. A method of a
class with a base keeps the friend (the name may be the base's)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """#include <ros/ros.h>
#include <X11/Xlib.h>
class Detector {
 public:
  explicit Detector(ros::NodeHandle & nh) : nh_(nh) { readParameters(); }
  bool readParameters() {
    nh_.param("image_view/enable_opencv", view_, true);
    if (XOpenDisplay(NULL)) {
      ROS_INFO("X server running");
    } else {
      view_ = false;
    }
    nh_.param("wait_key_delay", delay_, 3);
    return true;
  }
 private:
  ros::NodeHandle nh_;
  bool view_;
  int delay_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "detector");
  ros::NodeHandle nh("~");
  Detector detector(nh);
  ros::spin();
}
"""


def test_unknown_function_in_a_method_of_a_class_without_bases(write_tree) -> None:
    root = write_tree({"det/package.xml": package_xml("det"), "det/src/det.cpp": NODE})
    result = extract_cpp([str(root / "det" / "src" / "det.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "read") == [
        "~image_view/enable_opencv", "~wait_key_delay"]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes, codes
