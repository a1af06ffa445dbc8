"""A member that the one function writing it sets in a side of an ``if``, and that
otherwise holds what it was made with, names one call per value, each under its side
of that ``if`` (DOBOT's ``kRobotName``, set only ``if (robotNumber > 1)``, then the
prefix of every service name); a member another function writes too keeps ``?``."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
    #include <rclcpp/rclcpp.hpp>
    #include <std_msgs/msg/string.hpp>
    #include <std_srvs/srv/trigger.hpp>
    #include <string>

    class Robot : public rclcpp::Node {
     public:
      Robot() : Node("robot"), prefix_("arm"), base_("base") {}
      void init() {
        int number = 1;
        std::string name{""};
        declare_parameter("robot_number", 1);
        declare_parameter("robot_name", "robot");
        get_parameter("robot_number", number);
        get_parameter("robot_name", name);
        if (number > 1) {
          robot_ = name + "/";
        }
        std::string service = robot_ + "srv/enable";
        srv_ = create_service<std_srvs::srv::Trigger>(service, nullptr);
        if (number > 2) {
          prefix_ = "twin";
        }
        pub_ = create_publisher<std_msgs::msg::String>(prefix_ + "/state", 10);
        if (number > 3) {
          other_ = "far";
        }
        sub_pub_ = create_publisher<std_msgs::msg::String>(other_ + "/status", 10);
        auto later_name = [this]() { base_ = "renamed"; };
        base_pub_ = create_publisher<std_msgs::msg::String>(base_ + "/out", 10);
        later_name();
      }
      void later() { other_ = "changed"; }
     private:
      std::string robot_;
      std::string prefix_;
      std::string other_;
      std::string base_;
      rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr srv_;
      rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_, sub_pub_, base_pub_;
    };

    int main(int argc, char ** argv) {
      rclcpp::init(argc, argv);
      auto node = std::make_shared<Robot>();
      node->init();
      rclcpp::spin(node);
    }
    """


def test_a_member_set_in_a_branch_names_a_call_per_value(write_tree):
    root = write_tree({
        "src/demo/package.xml": package_xml("demo", "ament_cmake"),
        "src/demo/CMakeLists.txt": "project(demo)\nadd_executable(robot src/robot.cpp)\n",
        "src/demo/src/robot.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/demo/src/robot.cpp")], scan([str(root)]),
                         cache_dir=None)
    found = sorted((c.kind, c.name, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind in ("publish", "server"))
    # robot_: the empty string it is made with, or the parameter's value and "/"
    enable = [f for f in found if f[0] == "server"]
    assert [(name, conditions) for _, name, conditions in enable] == [
        ("?/srv/enable", (("if", "number > 1"),)),
        ("srv/enable", (("else", "number > 1"),)),
    ] or [(name.replace("?", "robot"), conditions) for _, name, conditions in enable] == [
        ("robot/srv/enable", (("if", "number > 1"),)),
        ("srv/enable", (("else", "number > 1"),)),
    ]
    published = [f for f in found if f[0] == "publish"]
    assert ("publish", "arm/state", (("else", "number > 2"),)) in published
    assert ("publish", "twin/state", (("if", "number > 2"),)) in published
    # other_ is written in later() too: what it holds in init() is not known
    assert ("publish", "?/status", ()) in published
    # a lambda's write runs when it is called: after the read here
    assert ("publish", "base/out", ()) in published
    assert len(published) == 4
