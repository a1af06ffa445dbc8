"""Stand-in gaps seen on real ROS 2 code (bench/README, helper surveyF): each left a C++
error in a function of a node, which made the node partial where that function calls the
ROS API (Stereolabs' zed_components in RoboFEI@Work's Caramelo workspace)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros2_main

CASES = {
    # rmw/rmw.h's middleware name, which rclcpp brings (its subscription_base.hpp
    # includes rmw/rmw.h): ZedCameraOne logs it in getDebugParams, beside its parameters
    "rmw_identifier_through_rclcpp": (
        "",
        "  const char* rmw = rmw_get_implementation_identifier();\n"
        "  const char* format = rmw_get_serialization_format();\n"),
    "rmw_identifier_of_rmw_h": (
        "#include <rmw/rmw.h>\n#include <string>\n",
        "  std::string name(rmw_get_implementation_identifier());\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros2_main(include, body), "ament_cmake", "jazzy")
