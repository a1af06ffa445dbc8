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
