"""Boost.Program_options, the command-line options of tools and nodes, stands in
(``boost/program_options.hpp`` and every ``boost/program_options/...`` header). Declared
permissively, ``boost::program_options::notify(vm);`` read as a declaration of a second
``vm`` of a class ``notify``, an error in ``main`` next to its ROS calls: MoveIt's
warehouse broadcast and save tools were partial for it."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <boost/program_options/parsers.hpp>
#include <boost/program_options/variables_map.hpp>
#include <iostream>

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("publish_scene");
  double delay = 0.001;
  boost::program_options::options_description desc;
  desc.add_options()("help", "Show help message")(
    "scene", boost::program_options::value<std::string>(), "Scene to publish.")(
    "delay", boost::program_options::value<double>()->default_value(delay), "Delay (s)");
  boost::program_options::variables_map vm;
  boost::program_options::store(boost::program_options::parse_command_line(argc, argv, desc), vm);
  boost::program_options::notify(vm);
  if (vm.count("help")) {
    std::cout << desc << std::endl;
    return 1;
  }
  delay = vm["delay"].as<double>();
  auto pub = node->create_publisher<std_msgs::msg::String>("planning_scene", 10);
  std_msgs::msg::String scene;
  scene.data = vm["scene"].as<std::string>();
  pub->publish(scene);
  return 0;
}
"""


def test_program_options_parse_beside_ros_calls(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("tools", "ament_cmake"))
    source = tmp_path / "broadcast.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "planning_scene")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
