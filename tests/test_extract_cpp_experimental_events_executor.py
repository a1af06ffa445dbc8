"""rclcpp's events executor where Iron and Jazzy declare it,
``rclcpp::experimental::executors::EventsExecutor`` (bitbots_main's emergency, head mover,
hcm and vision nodes spin on one: ``rclcpp::experimental::executors::EventsExecutor::
SharedPtr exec = std::make_shared<...>()``); the stand-in declared it only in
``rclcpp::executors`` (where later releases moved it), so the main function that makes
the node was a C++ error (139 CPP_PARSE_ERROR in bitbots_main)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <rclcpp/experimental/executors/events_executor/events_executor.hpp>
#include <std_msgs/msg/bool.hpp>
#include <thread>

class Listener : public rclcpp::Node {
public:
  Listener() : Node("listener") {
    pub_ = create_publisher<std_msgs::msg::Bool>("stop", 1);
  }
private:
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr pub_;
};

void thread_spin(rclcpp::experimental::executors::EventsExecutor::SharedPtr executor) {
  executor->spin();
}

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<Listener>();
  rclcpp::experimental::executors::EventsExecutor::SharedPtr exec =
      std::make_shared<rclcpp::experimental::executors::EventsExecutor>();
  rclcpp::experimental::executors::EventsExecutor plain;
  plain.add_node(node);
  exec->add_node(node);
  std::thread spinning(thread_spin, exec);
  spinning.join();
  rclcpp::executors::EventsExecutor later;
  rclcpp::shutdown();
}
"""


def test_the_experimental_events_executor_is_declared(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_NODE_PARTIAL")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "stop"] == [
        ("publish", "stop")]
