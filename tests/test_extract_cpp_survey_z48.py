"""What real ROS 2 code needed of the C++ extraction (survey Z48).

- naoqi_driver2's ``src/event/audio.hpp`` includes ``"../src/publishers/basic.hpp"``: not
  found beside it (``src/event/../src``), found through the package's include folder
  (``include/../src/publishers/basic.hpp``), as its CMakeLists' ``include_directories(
  "include")`` makes the compiler search. The parse searches the include folders through
  one header map, in which a name with ``..`` parts was a miss: an empty stand-in took
  the header's place, the publisher class template it defines was unknown and the
  driver's audio and touch publishers were lost (the node partial)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

CMAKE = """\
cmake_minimum_required(VERSION 3.5)
project(z48)
find_package(rclcpp REQUIRED)
include_directories("include")
add_executable(talker src/main.cpp src/event/audio.cpp)
"""

BASIC = """\
#pragma once
#include <string>
#include <rclcpp/rclcpp.hpp>
template<class T>
class BasicPublisher {
 public:
  explicit BasicPublisher(const std::string& topic) : topic_(topic) {}
  void reset(rclcpp::Node* node) { pub_ = node->create_publisher<T>(topic_, 10); }
 private:
  std::string topic_;
  typename rclcpp::Publisher<T>::SharedPtr pub_;
};
"""

AUDIO_HPP = """\
#pragma once
#include <std_msgs/msg/string.hpp>
#include "../src/publishers/basic.hpp"
class AudioEvent {
 public:
  AudioEvent() : publisher_("audio") {}
  void resetPublisher(rclcpp::Node* node);
 private:
  BasicPublisher<std_msgs::msg::String> publisher_;
};
"""

AUDIO_CPP = """\
#include "audio.hpp"
void AudioEvent::resetPublisher(rclcpp::Node* node) { publisher_.reset(node); }
"""

MAIN = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include "event/audio.hpp"
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("talker");
  AudioEvent event;
  event.resetPublisher(node.get());
  rclcpp::spin(node);
  return 0;
}
"""


def test_an_include_with_dot_dot_found_through_an_include_folder(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("z48", "ament_cmake").replace(
        "</license>", "</license><depend>rclcpp</depend><depend>std_msgs</depend>"))
    (tmp_path / "CMakeLists.txt").write_text(CMAKE)
    (tmp_path / "include" / "z48").mkdir(parents=True)
    (tmp_path / "include" / "z48" / "tools.hpp").write_text("#pragma once\n")
    (tmp_path / "src" / "publishers").mkdir(parents=True)
    (tmp_path / "src" / "event").mkdir()
    (tmp_path / "src" / "publishers" / "basic.hpp").write_text(BASIC)
    (tmp_path / "src" / "event" / "audio.hpp").write_text(AUDIO_HPP)
    (tmp_path / "src" / "event" / "audio.cpp").write_text(AUDIO_CPP)
    (tmp_path / "src" / "main.cpp").write_text(MAIN)
    sources = [str(tmp_path / "src" / "main.cpp"), str(tmp_path / "src" / "event" / "audio.cpp")]
    result = extract_cpp(sources, scan([str(tmp_path)]), cache_dir=None)
    assert not [d for d in result.diagnostics if d.code == "CPP_INCLUDE_MISSING"]
    assert [(c.kind, c.name, c.type) for c in result.calls if c.kind == "publish"] == [
        ("publish", "audio", "std_msgs/msg/String")]


CAMERAS = """\
#include <memory>
#include <string>
#include <rclcpp/rclcpp.hpp>
#include <image_transport/image_transport.hpp>
class CameraPublisher {
 public:
  explicit CameraPublisher(const std::string& topic) : topic_(topic) {}
  void reset(rclcpp::Node* node) { pub_ = image_transport::create_camera_publisher(node, topic_); }
 private:
  std::string topic_;
  image_transport::CameraPublisher pub_;
};
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("driver");
  auto front = std::make_shared<CameraPublisher>("camera/front/image_raw");
  auto bottom = std::make_shared<CameraPublisher>("camera/bottom/image_raw");
  front->reset(node.get());
  bottom->reset(node.get());
  rclcpp::spin(node);
  return 0;
}
"""


def test_a_camera_publisher_class_constructed_twice_has_two_info_topics(tmp_path) -> None:
    # naoqi_driver2's CameraPublisher, made once per camera with its image topic: each
    # construction's camera_info is beside its image topic (image_transport's
    # getCameraInfoTopic), not one ``camera_info`` for all of them
    (tmp_path / "package.xml").write_text(package_xml("z48", "ament_cmake").replace(
        "</license>", "</license><depend>rclcpp</depend><depend>image_transport</depend>"))
    source = tmp_path / "driver.cpp"
    source.write_text(CAMERAS)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert sorted((c.name, c.camera_of) for c in result.calls if c.kind == "publish") == [
        ("camera/bottom/image_raw", None), ("camera/front/image_raw", None),
        ("camera_info", "camera/bottom/image_raw"), ("camera_info", "camera/front/image_raw")]


QOS = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "vendor_common/qos.hpp"
namespace nvidia { namespace vendor { namespace slam {
class SlamNode : public rclcpp::Node {
 public:
  explicit SlamNode(const rclcpp::NodeOptions& options)
  : Node("slam", options),
    pub_(create_publisher<std_msgs::msg::String>(
      "slam/status", ::vendor::common::ParseQosString("DEFAULT"))) {}
 private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}}}
"""


def test_a_global_namespace_named_as_a_nested_one_is_declared(tmp_path) -> None:
    # isaac_ros_visual_slam's node, in ``namespace nvidia::isaac_ros``, writes
    # ``::isaac_ros::common::ParseQosString(..)`` (isaac_ros_common, not in the
    # workspace): clang said "'isaac_ros' is not a class, namespace, or enumeration",
    # which no permissive declaration answered, and the 24 publishers whose QoS it gives
    # were lost
    (tmp_path / "package.xml").write_text(package_xml("z48", "ament_cmake").replace(
        "</license>", "</license><depend>rclcpp</depend><depend>std_msgs</depend>"))
    source = tmp_path / "slam.cpp"
    source.write_text(QOS)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "slam/status")]
    assert not [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]


TRIM = """\
#include <string>
#include <vector>
#include <string_view>
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
class Synchronizer : public rclcpp::Node {
 public:
  Synchronizer() : Node("synchronizer") {
    auto names = declare_parameter<std::vector<std::string>>("camera_names", {});
    for (auto & name : names) {
      name.erase(0, name.find_first_not_of('/'));
      name.erase(name.find_last_not_of('/') + 1);
      std::string_view view(name);
      if (view.find_last_not_of(' ') == std::string_view::npos) { continue; }
      pubs_.push_back(create_publisher<std_msgs::msg::String>(name + "/emitter", 10));
    }
  }
 private:
  std::vector<rclcpp::Publisher<std_msgs::msg::String>::SharedPtr> pubs_;
};
"""


def test_the_char_forms_of_find_first_not_of_and_find_last_not_of(tmp_path) -> None:
    # nvblox's multi_realsense_emitter_synchronizer trims each camera name with
    # ``find_first_not_of('/')``: the stand-in string had only the string forms, the
    # constructor was a C++ error and its publishers possibly missed (the node partial)
    (tmp_path / "package.xml").write_text(package_xml("z48", "ament_cmake").replace(
        "</license>", "</license><depend>rclcpp</depend><depend>std_msgs</depend>"))
    source = tmp_path / "sync.cpp"
    source.write_text(TRIM)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert not [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "camera_names"), ("publish", "?/emitter")]
