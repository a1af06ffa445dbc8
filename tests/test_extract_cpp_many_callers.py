"""A wrapper of the ROS API defined in one file of a node and called from another with
many names (realsense2_camera's ``Parameters::setParam``, called with each of ~30
parameter names): one call per name, up to ``links.MAX_VALUES``, not one ``?`` for all."""

from __future__ import annotations

import pytest
from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#include <rclcpp/rclcpp.hpp>
class Params {
public:
  explicit Params(rclcpp::Node & node) : node_(node) {}
  double get(const std::string & name, double initial);
private:
  rclcpp::Node & node_;
};
"""
WRAPPER = """\
#include "params.hpp"
double Params::get(const std::string & name, double initial) {
  return node_.declare_parameter(name, initial);
}
"""


def caller(names: list[str]) -> str:
    return """\
#include "params.hpp"
class Driver : public rclcpp::Node {
public:
  Driver() : Node("driver"), params_(*this) {
    std::string name;
""" + "".join(f'    name = "{n}";\n    params_.get(name, 1.0);\n' for n in names) + """\
  }
  Params params_;
};
"""


def declared(tmp_path, names: list[str]) -> list[str]:
    (tmp_path / "package.xml").write_text(package_xml("drv", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    (tmp_path / "include").mkdir()
    (tmp_path / "include" / "params.hpp").write_text(HEADER)
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "params.cpp").write_text(WRAPPER)
    (tmp_path / "src" / "driver.cpp").write_text(caller(names))
    result = extract_cpp([str(tmp_path / "src" / "params.cpp"),
                          str(tmp_path / "src" / "driver.cpp")],
                         scan([str(tmp_path)]), cache_dir=None)
    return sorted(c.name for c in result.calls if c.kind == "declare")


def test_twenty_callers_name_twenty_parameters(tmp_path) -> None:
    names = [f"gain_{i}" for i in range(20)]
    assert declared(tmp_path, names) == sorted(names)


def test_two_hundred_callers_name_two_hundred_parameters(tmp_path) -> None:
    # OrbbecSDK_ROS2's OBCameraNode::getParameters calls its setAndGetNodeParameter with
    # ~180 names, which Parameters::setParam in another file declares: over the bound
    # of 32, all were one '?', which every parameter the launch file sets could be
    names = [f"gain_{i}" for i in range(200)]
    assert declared(tmp_path, names) == sorted(names)


def test_more_names_than_the_bound_are_one_unknown(tmp_path) -> None:
    from haros_arch.extract.cpp.links import MAX_VALUES

    assert declared(tmp_path, [f"gain_{i}" for i in range(MAX_VALUES + 8)]) == ["?"]



@pytest.mark.parametrize("template", [True, False])
def test_many_callers_in_the_function_s_own_file_name_its_parameters(tmp_path, template) -> None:
    # OrbbecSDK_ROS2's OBCameraNode::setAndGetNodeParameter<T>(param, name, default),
    # a member template defined in ob_camera_node.cpp and called there ~180 times,
    # passes the name to Parameters::setParam of another file: more calls in the file
    # than it reads for one value (CallSites.MAX_SITES) gave '?', not one name per
    # call (a plain method too)
    (tmp_path / "package.xml").write_text(package_xml("drv", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    (tmp_path / "include").mkdir()
    (tmp_path / "include" / "params.hpp").write_text(HEADER)
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "params.cpp").write_text(WRAPPER)
    names = [f"gain_{i}" for i in range(20)]
    head, kind = ("template <class T> ", "T") if template else ("", "double")
    (tmp_path / "src" / "driver.cpp").write_text(f"""\
#include "params.hpp"
class Driver : public rclcpp::Node {{
public:
  Driver();
  {head}void setAndGet({kind} & value, const std::string & name, {kind} initial);
  Params params_;
  double gain_;
}};
{head}void Driver::setAndGet({kind} & value, const std::string & name, {kind} initial) {{
  value = params_.get(name, initial);
}}
Driver::Driver() : Node("driver"), params_(*this) {{
""" + "".join(f'  setAndGet(gain_, "{n}", 1.0);\n' for n in names) + "}\n")
    result = extract_cpp([str(tmp_path / "src" / "params.cpp"),
                          str(tmp_path / "src" / "driver.cpp")],
                         scan([str(tmp_path)]), cache_dir=None)
    assert sorted(c.name for c in result.calls if c.kind == "declare") == sorted(names)
