"""Stand-in gaps seen on real code (bench/README, survey Z57): consai_ros2's
geometry_tools.hpp keeps ``std::complex<double>`` members, its ControlParams compares two
``std::tie(...)`` tuples, its controller takes gains as ``_Float64`` (glibc's typedef for
a C++ compiler without the type); lidar_localization_ros2 compares a
``steady_clock::time_point`` with a default one. The stand-ins had no ``std::complex``,
no tuple comparison, no ``_Float64`` and no ``==`` / ``!=`` / ``<=`` / ``-=`` of a
time_point: each was a C++ error (or a name declared permissively)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <tuple>

struct Params {
  double a = 0.0;
  _Float64 b = 1.0;
  auto tie() const { return std::tie(a, b); }
  bool operator==(const Params & other) const { return tie() == other.tie(); }
  bool operator!=(const Params & other) const { return tie() != other.tie(); }
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("node");
  std::complex<double> center(1.0, 2.0);
  std::complex<double> rotation = std::polar(1.0, 0.5);
  const auto moved = (std::complex<double>(3.0, 4.0) - center) * std::conj(rotation);
  const double angle = std::arg(moved) + std::abs(moved) + moved.real() * 2.0;
  std::chrono::steady_clock::time_point last{};
  last -= std::chrono::milliseconds(5);
  const bool set = last != std::chrono::steady_clock::time_point{} &&
    last <= std::chrono::steady_clock::now();
  Params p, q;
  if (set || p == q || angle > 0.0) {
    auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);
  }
  rclcpp::spin(node);
}
"""


def test_complex_tuple_compare_float64_time_point_equality(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("node", "ament_cmake"))
    source = tmp_path / "node.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [(c.kind, c.name) for c in result.calls if c.name == "out"] == [("publish", "out")]
