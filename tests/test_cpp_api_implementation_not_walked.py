"""A package whose API the rows model, modelled itself (``models build`` of
image_transport, topic_tools, tf2_ros): its own definitions of the functions the rows
name are the implementation of that API. A call of one anywhere is the row's call at
its site; the body is no code of the node's, walked or not. Jazzy's image_transport
defines ``create_camera_publisher(node, base_topic, ...)`` as ``return
CameraPublisher(node, base_topic, ...)`` (src/image_transport.cpp:85), which its
``ImageTransport::advertiseCamera`` calls (line 200): walked as code of its library,
they gave every program linking the library an image and a ``camera_info`` publisher
of their own, named ``?``; the rebuilt model of republish and list_transports had
them."""

from __future__ import annotations

from haros_arch import cmake
from haros_arch.extract import extract_nodes
from haros_arch.workspace import scan

PACKAGE = """<?xml version="1.0"?>
<package format="3"><name>image_transport</name><version>5.0.0</version>
<description>d</description><maintainer email="a@b.c">m</maintainer>
<license>BSD</license><buildtool_depend>ament_cmake_ros</buildtool_depend>
<depend>rclcpp</depend><depend>sensor_msgs</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

CMAKE = """
cmake_minimum_required(VERSION 3.16)
project(image_transport)
find_package(ament_cmake_ros REQUIRED)
find_package(rclcpp REQUIRED)
find_package(sensor_msgs REQUIRED)
add_library(${PROJECT_NAME} src/image_transport.cpp)
target_include_directories(${PROJECT_NAME} PUBLIC include)
ament_target_dependencies(${PROJECT_NAME} rclcpp sensor_msgs)
add_executable(camera_node src/camera_node.cpp)
target_link_libraries(camera_node ${PROJECT_NAME})
ament_package()
"""

LIBRARY = """#include <string>
#include "image_transport/image_transport.hpp"
#include "rclcpp/rclcpp.hpp"

namespace image_transport
{
CameraPublisher create_camera_publisher(
  rclcpp::Node * node, const std::string & base_topic,
  rmw_qos_profile_t custom_qos, rclcpp::PublisherOptions pub_options)
{
  return CameraPublisher(node, base_topic, custom_qos, pub_options);
}

struct ImageTransport::Impl
{
  rclcpp::Node::SharedPtr node_;
};

CameraPublisher ImageTransport::advertiseCamera(
  const std::string & base_topic, uint32_t queue_size, bool latch)
{
  (void) latch;
  rmw_qos_profile_t custom_qos = rmw_qos_profile_default;
  custom_qos.depth = queue_size;
  return create_camera_publisher(impl_->node_.get(), base_topic, custom_qos);
}
}  // namespace image_transport
"""

PROGRAM = """#include <memory>
#include "image_transport/image_transport.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("camera");
  auto pub = image_transport::create_camera_publisher(
    node.get(), "image", rmw_qos_profile_default, rclcpp::PublisherOptions());
  rclcpp::spin(node);
  return 0;
}
"""


def test_the_package_s_own_implementation_of_a_row_is_not_walked(write_tree) -> None:
    root = write_tree({
        "image_transport/package.xml": PACKAGE,
        "image_transport/CMakeLists.txt": CMAKE,
        "image_transport/src/image_transport.cpp": LIBRARY,
        "image_transport/src/camera_node.cpp": PROGRAM,
    })
    ws = scan([str(root)])
    package = ws.packages["image_transport"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = next(n for n in package.nodes if n.executable == "camera_node")
    found = sorted((c.kind, c.name, c.type, c.location.file, c.location.line)
                   for c in node.calls)
    # the row's calls at the program's site, and no call at the library's line 11
    assert found == [
        ("publish", "camera_info", "sensor_msgs/msg/CameraInfo",
         "image_transport/src/camera_node.cpp", 9),
        ("publish", "image", "sensor_msgs/msg/Image",
         "image_transport/src/camera_node.cpp", 9)], found
    assert node.completeness == "complete", node.completeness_reasons



LISTER = """#include <cstdio>
#include <string>
#include "pluginlib/class_loader.hpp"
#include "image_transport/publisher_plugin.hpp"

int main(int argc, char ** argv)
{
  pluginlib::ClassLoader<image_transport::PublisherPlugin> loader(
    "image_transport", "image_transport::PublisherPlugin");
  for (const std::string & name : loader.getDeclaredClasses()) {
    auto plugin = loader.createUniqueInstance(name);
    std::printf("%s\\n", name.c_str());
  }
  return 0;
}
"""


def test_nor_in_a_program_that_does_not_call_it(write_tree) -> None:
    # list_transports links the library, calls none of its API and makes no node (it
    # lists the transport plugins): it had the library's camera publisher, named ``?``,
    # and its ``camera_info``
    root = write_tree({
        "image_transport/package.xml": PACKAGE,
        "image_transport/CMakeLists.txt": CMAKE,
        "image_transport/src/image_transport.cpp": LIBRARY,
        "image_transport/src/camera_node.cpp": LISTER,
    })
    ws = scan([str(root)])
    package = ws.packages["image_transport"]
    package.nodes, _ = cmake.parse_package(package, ws)
    extract_nodes(package.nodes, ws, cache_dir=None, jobs=1)
    node = next(n for n in package.nodes if n.executable == "camera_node")
    assert [(c.kind, c.name, c.location.line) for c in node.calls] == []
    assert node.completeness == "complete", node.completeness_reasons
