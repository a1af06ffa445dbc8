"""gencpp declares a ``_<field>_type`` typedef for each field of a ROS 1 message
(``typedef std::vector<int32_t> _buttons_type;``) and code names it: rotors_joy_interface's
``typedef sensor_msgs::Joy::_buttons_type ButtonType;`` (joy.h:57). The synthesised
headers had none, an error in the class and in each function using the type."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, interfaces
from haros_arch.workspace import scan

SOURCE = """\
#include <ros/ros.h>
#include <sensor_msgs/Joy.h>
#include <pkg/Pose.h>
class Joy {
  typedef sensor_msgs::Joy::_buttons_type ButtonType;
 public:
  explicit Joy(const pkg::Pose::_names_type& names) {
    ros::NodeHandle pnh("~");
    pnh.param("button_count", count_, static_cast<int>(names.size()));
    sub_ = nh_.subscribe("joy", 10, &Joy::callback, this);
  }
  void callback(const sensor_msgs::JoyConstPtr& msg) { last_ = msg->buttons; }
 private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  ButtonType last_;
  pkg::Pose::_covariance_type covariance_;
  int count_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "joy");
  Joy joy(pkg::Pose::_names_type(1, "x"));
  ros::spin();
}
"""


def test_field_type_typedefs_are_declared(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>sensor_msgs</depend></package>"),
        "pkg/msg/Pose.msg": "float64[36] covariance\nstring[] names\nint32 KIND=1\n",
        "pkg/src/joy.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "joy.cpp")], scan([str(root)]),
                         cache_dir=None, jobs=1)
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_CALL_MISSED")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("read", "~button_count"), ("subscribe", "joy")]


def test_rendered_typedefs() -> None:
    text = interfaces.render(interfaces.parse_definition(
        "pkg", "Cam", "float64[9] K\nstring[] names\nstd_msgs/Header header\nint32 A=1\n"))
    assert "typedef boost::array<double, 9> _K_type;" in text
    assert "typedef std::vector<std::string> _names_type;" in text
    assert "typedef std_msgs::Header _header_type;" in text
    assert "_A_type" not in text  # constants have none
