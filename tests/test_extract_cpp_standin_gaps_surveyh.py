"""Stand-in gaps seen on real ROS 2 code (bench/README, helper surveyH): each left a C++
error in a function of a node, which made the node partial where that function calls the
ROS API (smarc2's pid_actuator_trim: ``declare_parameters<std::double_t>("", {...})``;
rapidjson's ``std::wcslen`` in lunabot_ros' livox_ros_driver2)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros2_main

CASES = {
    # <cmath>'s evaluation types, the template argument of a declaration of several
    "std_double_t": (
        "#include <cmath>\n",
        "  std::double_t gain = 0.1;\n  std::float_t half = 0.5f;\n"
        "  ::double_t other = gain + half;\n"),
    "math_h_float_t": (
        "#include <math.h>\n",
        "  float_t x = 1.0f;\n  double_t y = x;\n"),
    # <cwchar>'s wide string length (rapidjson's strfunc.h, in livox_ros_driver2)
    "std_wcslen": (
        "#include <cwchar>\n",
        "  const wchar_t* text = L\"lidar\";\n  auto n = std::wcslen(text);\n"
        "  int same = std::wcscmp(text, L\"x\") + wcsncmp(text, text, n);\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros2_main(include, body), "ament_cmake", "jazzy")
