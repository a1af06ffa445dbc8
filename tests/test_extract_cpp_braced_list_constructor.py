"""A braced list that builds a class by one of its constructors, as the elements of a
``std::vector<T>{{...}, {...}}``, is a call of that constructor with the list's
elements as arguments. mrover-ros2 c7572baf declares each node's parameters through
``ParameterWrapper::declareParameters(this, params)``, ``params`` a vector of
``{"alpha", mAlpha, 0.05}``, a class with a constructor per type of variable: clang
types such an element ``void`` and keeps no call of the constructor, so no file of the
node was seen to construct the class, and the declarations, made once per constructor
(their name a member that each constructor sets from its parameter), were all left out:
the node was complete with none of its parameters, 60 parameter-set-not-read warnings.
And a variable such a list passes to the constructor's non-const reference parameter
may be written there: its ZedWrapper's ``std::format("/{}/right/image", mDeviceName)``,
``mDeviceName`` in ``{"device_name", mDeviceName, "zed"}``, was read as ``//right/image``
(the member taken as never written, its empty default), two instances publishing it.
A ``float`` member with a ``double`` literal, ``{"model_score_threshold",
mModelScoreThreshold, 0.75}``, picks the ``float&`` overload: no conversion binds a
non-const reference; a member of a class whose header is missing (its aruco
``mDetectorParams->adaptiveThreshConstant``) is of a type not known, which may be it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

HEADER = """#pragma once
#include <rclcpp/rclcpp.hpp>
#include <string>
#include <vector>
namespace rov {
class Setting {
public:
  Setting(std::string key, int& slot, int fallback = 0)
  : key_{std::move(key)}, type_{rclcpp::ParameterType::PARAMETER_INTEGER} {
    (void)slot; (void)fallback; }
  Setting(std::string key, double& slot, double fallback = 0.0)
  : key_{std::move(key)}, type_{rclcpp::ParameterType::PARAMETER_DOUBLE} {
    (void)slot; (void)fallback; }
  Setting(std::string key, float& slot, float fallback = 0.0)
  : key_{std::move(key)}, type_{rclcpp::ParameterType::PARAMETER_DOUBLE} {
    (void)slot; (void)fallback; }
  Setting(std::string key, std::string& slot, std::string fallback = "")
  : key_{std::move(key)}, type_{rclcpp::ParameterType::PARAMETER_STRING},
    text_{&slot} { (void)fallback; }
  static void declareAll(rclcpp::Node* node, std::vector<Setting>& settings) {
    for (auto& setting : settings) {
      node->declare_parameter(setting.key_, setting.type_);
    }
  }
  std::string key_;
  rclcpp::ParameterType type_;
  std::string* text_ = nullptr;
};
}  // namespace rov
"""

NODE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <vendor/tuning.hpp>
#include "setting.hpp"
namespace rov {
class Arm : public rclcpp::Node {
public:
  Arm() : Node("arm") {
    std::vector<Setting> settings{
      {"gain", gain_, 0.5},
      {"joints", joints_, 6},
      {"device", device_, "cam"},
      {"ratio", ratio_, 0.75},
      {"threshold", tuning_->threshold, 7.0},
    };
    Setting::declareAll(this, settings);
    pub_ = create_publisher<std_msgs::msg::String>("/" + device_ + "/status", 1);
  }
private:
  double gain_;
  int joints_;
  float ratio_;
  std::shared_ptr<vendor::Tuning> tuning_;
  std::string device_{};
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
}  // namespace rov
int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rov::Arm>());
}
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(rov)
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
add_executable(arm src/arm.cpp)
ament_target_dependencies(arm rclcpp std_msgs)
install(TARGETS arm DESTINATION lib/${PROJECT_NAME})
ament_package()
"""


def test_braced_elements_construct_by_their_constructor(write_tree):
    root = write_tree({
        "src/rov/package.xml": package_xml("rov", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend><depend>std_msgs</depend></package>"),
        "src/rov/CMakeLists.txt": CMAKE,
        "src/rov/src/setting.hpp": HEADER,
        "src/rov/src/arm.cpp": NODE,
        "project.yaml": "project: p\ndistro: humble\nworkspace: src\n"})
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (node,) = [n for n in model.nodes if n.package == "rov"]
    assert sorted(c.name for c in node.calls if c.kind == "declare") == [
        "device", "gain", "joints", "ratio", "threshold"]
    # the constructor takes ``device_`` by non-const reference (and keeps its address,
    # where a parameter's value goes later): not known to stay empty
    assert [c.name for c in node.calls if c.kind == "publish"] == ["/?/status"]
