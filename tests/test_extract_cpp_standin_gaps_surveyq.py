"""Stand-in gaps seen on real ROS 2 code (bench/README, helper surveyQ): each left a C++
error in a function of a node, which made the node partial where that function calls the
ROS API (kalman_robot's arm hardware component, ``class HARDWARE_INTERFACE_PUBLIC
ArmSystem``, whose ``hardware_interface/visibility_control.h`` was an empty stand-in: the
class did not parse and its node's subscription was lost)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros2_main

VISIBILITY = {
    "hardware_interface": "HARDWARE_INTERFACE",
    "controller_interface": "CONTROLLER_INTERFACE",
    "controller_manager": "CONTROLLER_MANAGER",
    "joint_limits": "JOINT_LIMITS",
}


@pytest.mark.parametrize("package", sorted(VISIBILITY))
def test_ros2_control_visibility_macros(tmp_path, package: str) -> None:
    prefix = VISIBILITY[package]
    include = (f"#include <{package}/visibility_control.h>\n"
               f"class {prefix}_PUBLIC Arm {{\npublic:\n"
               f"  {prefix}_PUBLIC int joints() const;\n"
               f"  {prefix}_LOCAL int spare;\n}};\n"
               f"class {prefix}_PUBLIC_TYPE Hand {{}};\n"
               f"{prefix}_EXPORT int exported();\n{prefix}_IMPORT int imported();\n")
    body = "  Arm arm;\n  Hand hand;\n  int n = arm.joints() + exported() + imported();\n"
    assert_call_found(tmp_path, ros2_main(include, body), "ament_cmake", "jazzy")


# std::optional's accessors ref-qualified as the standard's: the value of an rvalue
# optional binds to an rvalue reference (kalman_robot's bt_panel_node,
# ``MissionState{PanelLayout::read_yaml(path, logger).value()}`` of a constructor taking
# ``PanelLayout&&``), an lvalue's to an lvalue reference, and not to an rvalue one
OPTIONAL = """#include <optional>
#include <string>
struct Layout { std::string name; };
struct Mission { explicit Mission(Layout&& layout); };
std::optional<Layout> read_layout(const std::string& path);
void keep(Layout& layout);
"""

OPTIONAL_BODY = """  Mission first{read_layout("a.yaml").value()};
  Mission second{*read_layout("b.yaml")};
  std::optional<Layout> held = read_layout("c.yaml");
  keep(held.value());
  keep(*held);
  Mission third{std::move(held).value()};
  const std::optional<Layout> fixed = read_layout("d.yaml");
  const Layout& seen = fixed.value();
  Layout copy = read_layout("e.yaml").value_or(Layout{});
"""


def test_an_rvalue_optional_gives_its_value_to_move_from(tmp_path) -> None:
    assert_call_found(tmp_path, ros2_main(OPTIONAL, OPTIONAL_BODY), "ament_cmake", "jazzy")


def test_an_lvalue_optional_does_not_bind_to_an_rvalue_reference(tmp_path) -> None:
    # the standard's overloads, not one returning T&& always: C++ refuses this
    with pytest.raises(AssertionError):
        assert_call_found(tmp_path, ros2_main(
            OPTIONAL, "  std::optional<Layout> held = read_layout(\"c.yaml\");\n"
            "  Mission wrong{held.value()};\n"), "ament_cmake", "jazzy")


# OpenCV's small vectors in place and by scalars (kalman_robot's dead_reckoning node,
# ``mean_o2w_rvec += norm_rvec(...)``, ``/= static_cast<double>(n)``, ``*= kp``,
# ``mean_g_o.cross(g_w)``): four C++ errors there made the node partial
VEC = """#include <opencv2/core/mat.hpp>
cv::Vec3d norm_rvec(const cv::Vec3d& rvec);
"""

VEC_BODY = """  cv::Vec3d mean(0, 0, 0);
  const cv::Vec3d g(0, 0, -1);
  mean += norm_rvec(g);
  mean -= g;
  mean /= static_cast<double>(3);
  mean *= 0.5;
  cv::Vec3d axis = mean.cross(g);
  cv::Vec3d scaled = 2.0 * (mean + axis) / 4.0 - g * 3.0;
  double along = mean.dot(g) + scaled.mul(g)[0];
  cv::Matx33d rotation = cv::Matx33d::eye();
  rotation += cv::Matx33d::eye();
  rotation *= 0.5;
  cv::Matx33d half = rotation / 2.0;
"""


def test_opencv_vectors_in_place_and_by_scalars(tmp_path) -> None:
    assert_call_found(tmp_path, ros2_main(VEC, VEC_BODY), "ament_cmake", "jazzy")


# std::weak_ptr converts from a pointer of another class only when that pointer converts,
# as shared_ptr does (cabot-navigation's planner test hands its nav2_util lifecycle node to
# a nav2_core planner's configure, overloaded on Humble's and on Kilted's node: both
# overloads took it, "call to member function 'configure' is ambiguous")
WEAK = """#include <memory>
struct Base { virtual ~Base(); };
struct Legacy : Base {};
struct Kilted : Base {};
struct Derived : Legacy {};
struct Planner {
  void configure(const std::weak_ptr<Legacy>& node, int name);
  void configure(const std::weak_ptr<Kilted>& node, int name);
};
"""

WEAK_BODY = """  auto derived = std::make_shared<Derived>();
  Planner planner;
  planner.configure(derived, 1);
  std::weak_ptr<Derived> weak = derived;
  planner.configure(weak, 2);
  std::weak_ptr<Base> base = weak;
  base = derived;
"""


def test_weak_ptr_converts_only_what_converts(tmp_path) -> None:
    assert_call_found(tmp_path, ros2_main(WEAK, WEAK_BODY), "ament_cmake", "jazzy")


# a costmap layer's node_ is each release's: rclcpp_lifecycle's before Kilted, whose
# unqualified ``declare_parameter_if_not_declared(node, ...)`` finds nav2_util's alone
# (cabot-navigation's NavCogPathLayer, Humble: the Kilted node made it ambiguous with
# nav2's, five C++ errors in onInitialize), Kilted's nav2 node from Kilted on
LAYER = """#include <nav2_costmap_2d/costmap_layer.hpp>
#include <nav2_util/node_utils.hpp>
using nav2_util::declare_parameter_if_not_declared;
class PathLayer : public nav2_costmap_2d::CostmapLayer {
public:
  void onInitialize() override {
    auto node = node_.lock();
    declare_parameter_if_not_declared(node, name_ + ".width", rclcpp::ParameterValue(2.0));
    double width = 0.0;
    node->get_parameter(name_ + ".width", width);
  }
  void updateBounds(double, double, double, double*, double*, double*, double*) override {}
  void updateCosts(nav2_costmap_2d::Costmap2D&, int, int, int, int) override {}
  void reset() override {}
  bool isClearable() override { return false; }
};
"""

KILTED_LAYER = """#include <nav2_costmap_2d/costmap_layer.hpp>
class PathLayer : public nav2_costmap_2d::CostmapLayer {
public:
  void onInitialize() override {
    nav2::LifecycleNode::SharedPtr node = node_.lock();
    double width = node->declare_or_get_parameter(name_ + ".width", 2.0);
  }
  void updateBounds(double, double, double, double*, double*, double*, double*) override {}
  void updateCosts(nav2_costmap_2d::Costmap2D&, int, int, int, int) override {}
  void reset() override {}
  bool isClearable() override { return false; }
};
"""


@pytest.mark.parametrize("distro", ["humble", "jazzy"])
def test_a_layer_node_before_kilted_is_rclcpp_lifecycles(tmp_path, distro: str) -> None:
    assert_call_found(tmp_path, ros2_main(LAYER, ""), "ament_cmake", distro)


def test_a_layer_node_from_kilted_is_nav2s(tmp_path) -> None:
    assert_call_found(tmp_path, ros2_main(KILTED_LAYER, ""), "ament_cmake", "kilted")
