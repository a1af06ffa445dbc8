"""A missing header ``<Lib/Name.h>`` whose folder no ROS package can be named (REP 144:
lowercase letters, digits and underscores) is a library's, not a message of a package we
have no definition of: Autoware's polygon remover includes CGAL's
``<CGAL/Exact_predicates_inexact_constructions_kernel.h>``, which was synthesised as a
fieldless message; ``K::Point_2`` of it was then an error, ``PolygonCgal`` unknown made
the node's class invalid and its constructor's calls unresolved. Declared permissively,
the aliases hold and the class is whole."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

GEOMETRY = """#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <vector>
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using PointCgal = K::Point_2;
using PolygonCgal = std::vector<PointCgal>;
namespace remover::utils {
void to_cgal_polygon(const std::vector<double> & in, PolygonCgal & out);
}
"""

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include "remover/geometry.hpp"
namespace remover {
class Remover : public rclcpp::Node
{
public:
  explicit Remover(const rclcpp::NodeOptions & options);
protected:
  static PolygonCgal to_cgal(const std::vector<double> & in);
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  PolygonCgal polygon_;
};
Remover::Remover(const rclcpp::NodeOptions & options) : rclcpp::Node("remover", options)
{
  pub_ = this->create_publisher<std_msgs::msg::String>("removed", 10);
  this->declare_parameter<bool>("will_visualize");
}
PolygonCgal Remover::to_cgal(const std::vector<double> & in)
{
  PolygonCgal out;
  utils::to_cgal_polygon(in, out);
  return out;
}
}
"""


def test_a_missing_library_header_in_capitals_is_no_message(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("remover", "ament_cmake"))
    (tmp_path / "include" / "remover").mkdir(parents=True)
    (tmp_path / "include" / "remover" / "geometry.hpp").write_text(GEOMETRY)
    source = tmp_path / "remover.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "will_visualize"), ("publish", "removed")]
    codes = {d.code for d in result.diagnostics}
    assert "CPP_MESSAGE_UNKNOWN" not in codes and "CPP_CALL_UNRESOLVED" not in codes
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
    assert sum(d.code == "CPP_INCLUDE_MISSING" for d in result.diagnostics) == 2
