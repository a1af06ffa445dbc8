"""An error clang leaves inside a logging macro's arguments (``RCLCPP_INFO(logger, "%s",
mavlink::version)`` with mavlink's generated headers absent, ``ROS_INFO_STREAM(x <<
vendor.thing())``) cannot hide a ROS call: such a statement only writes a message. It
stays information (``CPP_PARSE_ERROR``) and leaves the node whole; one in any other
statement, or in a log statement that holds a ROS call site itself, still may hide a call."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

ROS2 = """
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Talker : public rclcpp::Node {
 public:
  Talker() : Node("talker") {
    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);
    STATEMENT
  }
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  std::string name_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>());
  return 0;
}
"""

ROS1 = """
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "talker");
  ros::NodeHandle nh;
  std::string name;
  ros::Publisher pub = nh.advertise<std_msgs::String>("chatter", 10);
  STATEMENT
  ros::spin();
  return 0;
}
"""

# a member std::string does not have: an error no declaration of unknown names repairs
MISSING = "name_.no_such_member()"


def _extract(tmp_path: Path, text: str):
    package = tmp_path / "src" / "talk"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("talk"))
    (package / "src" / "talk.cpp").write_text(text)
    return extract_cpp([str(package / "src" / "talk.cpp")], scan([str(tmp_path / "src")]),
                       cache_dir=None)


def _codes(result) -> list[str]:
    return [d.code for d in result.diagnostics]


def test_an_error_in_a_log_statement_hides_no_call(tmp_path: Path) -> None:
    statement = ('RCLCPP_INFO(\n      this->get_logger(), "version %s",\n      '
                 + MISSING + ');')
    result = _extract(tmp_path, ROS2.replace("STATEMENT", statement))
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "chatter")]
    assert "CPP_PARSE_ERROR" in _codes(result)  # still said, as information
    assert "CPP_ERROR_NEAR_CALL" not in _codes(result), result.diagnostics


def test_every_log_macro_form_of_both_ros_versions(tmp_path: Path) -> None:
    for index, (text, statement) in enumerate([
            (ROS2, 'RCLCPP_WARN_THROTTLE(get_logger(), *get_clock(), 1000, "%s", '
                   + MISSING + ');'),
            (ROS2, 'RCLCPP_INFO_STREAM(get_logger(), "a (b) \\"c)\\" " << ' + MISSING
                   + ' << \')\');'),
            (ROS1.replace("name_", "name"), 'ROS_INFO_STREAM_NAMED("talk", "v " << '
                   + MISSING.replace("name_", "name") + ');'),
            (ROS1, 'if (argc > 1) ROS_ERROR("%s", '
                   + MISSING.replace("name_", "name") + ');')]):
        result = _extract(tmp_path / str(index), text.replace("STATEMENT", statement))
        assert [(c.kind, c.name) for c in result.calls] == [("publish", "chatter")], index
        assert "CPP_PARSE_ERROR" in _codes(result), index
        assert "CPP_ERROR_NEAR_CALL" not in _codes(result), (index, result.diagnostics)


def test_the_same_error_in_another_statement_still_may_hide_a_call(tmp_path: Path) -> None:
    result = _extract(tmp_path, ROS2.replace("STATEMENT", "auto v = " + MISSING + ";"))
    assert "CPP_ERROR_NEAR_CALL" in _codes(result), result.diagnostics


def test_a_log_statement_that_holds_a_ros_call_still_may_hide_it(tmp_path: Path) -> None:
    statement = ('RCLCPP_INFO(get_logger(), "%s", create_publisher<std_msgs::msg::String>('
                 + MISSING + ', 10)->get_topic_name());')
    result = _extract(tmp_path, ROS2.replace("STATEMENT", statement))
    assert "CPP_ERROR_NEAR_CALL" in _codes(result), result.diagnostics


def test_an_error_after_a_log_statement_on_its_line_is_not_in_it(tmp_path: Path) -> None:
    statement = 'RCLCPP_INFO(get_logger(), "(");  auto v = ' + MISSING + ";"
    result = _extract(tmp_path, ROS2.replace("STATEMENT", statement))
    assert "CPP_ERROR_NEAR_CALL" in _codes(result), result.diagnostics
