"""``<regex>``'s iterators: the Fairino cobot's ROS 2 command server
(fairino_hardware, command_server.cpp) splits each command's arguments with
``std::regex_token_iterator iter_data(str.begin(), str.end(), re, -1)`` (its class
template arguments deduced) inside the functions that call the ROS API; the std
stand-ins had no regex_iterator nor regex_token_iterator, so each such function was a
C++ error near a ROS call and the node partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """
#include <list>
#include <regex>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>

class Commands : public rclcpp::Node
{
public:
  Commands() : Node("commands")
  {
    sub_ = create_subscription<std_msgs::msg::String>(
      "command", 10, [this](const std_msgs::msg::String::SharedPtr msg) { run(msg->data); });
  }

private:
  void run(std::string text)
  {
    std::regex comma(",");
    std::regex_token_iterator parts(text.begin(), text.end(), comma, -1);
    std::regex_token_iterator<std::string::iterator> end;
    std::list<std::string> words;
    while (parts != end) {
      words.push_back(parts->str());
      parts++;
    }
    std::regex word("[a-z]+");
    for (std::sregex_iterator it(text.cbegin(), text.cend(), word), stop; it != stop; ++it) {
      words.push_back(it->str(0));
    }
    for (std::sregex_token_iterator it(text.cbegin(), text.cend(), comma, {-1, 0}), stop;
         it != stop; ++it) {
      words.push_back(*it);
    }
    pub_ = create_publisher<std_msgs::msg::String>(words.front(), 10);
    status_ = create_publisher<std_msgs::msg::String>("status", 10);
  }

  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
};
"""


def test_regex_iterators_near_ros_calls(write_tree) -> None:
    root = write_tree({
        "pkg/package.xml": package_xml("pkg", "ament_cmake"),
        "pkg/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(pkg)\n"
                              "add_executable(commands src/commands.cpp)\n",
        "pkg/src/commands.cpp": SOURCE})
    result = extract_cpp([str(root / "pkg" / "src" / "commands.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
    assert [(c.kind, c.name) for c in result.calls] == [
        ("subscribe", "command"), ("publish", "?"), ("publish", "status")]
