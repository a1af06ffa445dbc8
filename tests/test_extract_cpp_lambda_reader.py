"""A local lambda that reads the parameter it is given on a handle it captures:
kr_mav_control's quadrotor simulator (a class template's constructor in a header) reads
eleven parameters with ``auto get_param = [&n](const std::string &param_name) { double
param; if (!n.hasParam(param_name)) ...; if (!n.getParam(param_name, param)) throw ...;
return param; }`` and ``quad_.setMass(get_param("mass"))``. In a template the call of the
lambda refers to its variable, not to the closure's ``operator()``: the reads were lost
(no call at all, the node complete, and "parameter set but never read" for each of its
eleven parameters); outside a template the captured handle's namespace was not known
(``?/mass``). Now each is a read of ``~mass`` (the captured handle is private), a double."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

LAMBDA = """
  auto get_param = [&n](const std::string &param_name) {
    double param;
    if (!n.hasParam(param_name))
      ROS_WARN("waiting for %s", param_name.c_str());
    if (!n.getParam(param_name, param))
      throw std::logic_error(param_name + " not set");
    return param;
  };
"""

IN_MAIN = """
#include <ros/ros.h>
int main(int argc, char **argv) {
  ros::init(argc, argv, "sim");
  ros::NodeHandle n("~");
""" + LAMBDA + """
  double mass = get_param("mass");
  double gravity = get_param("gravity");
  ros::spin();
}
"""

TEMPLATE_HEADER = """
#include <ros/ros.h>
struct Quad { void setMass(double) {} void setGravity(double) {} };
template <typename T, typename U>
class SimulatorBase {
 public:
  SimulatorBase(ros::NodeHandle &n);
 private:
  Quad quad_;
  double rate_;
};
template <typename T, typename U>
SimulatorBase<T, U>::SimulatorBase(ros::NodeHandle &n) {
  n.param("rate", rate_, 100.0);
""" + LAMBDA + """
  quad_.setMass(get_param("mass"));
  quad_.setGravity(get_param("gravity"));
}
"""

TEMPLATE_MAIN = """
#include "simulator_base.hpp"
class Simulator : public SimulatorBase<int, double> {
 public:
  explicit Simulator(ros::NodeHandle &nh) : SimulatorBase(nh) {}
};
int main(int argc, char **argv) {
  ros::init(argc, argv, "sim");
  ros::NodeHandle nh("~");
  Simulator sim(nh);
  ros::spin();
}
"""


def _reads(write_tree, files: dict[str, str]) -> list[tuple]:
    root = write_tree({"sim/package.xml": package_xml("sim"),
                       **{f"sim/src/{name}": text for name, text in files.items()}})
    result = extract_cpp([str(root / "sim" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    return sorted(((c.name, c.type) for c in result.calls if c.kind == "read"), key=repr)


@pytest.mark.parametrize("where", ["main", "header template", "main template"])
def test_each_call_of_the_lambda_reads_its_parameter(write_tree, where: str) -> None:
    if where == "main":
        files = {"main.cpp": IN_MAIN}
        expected = [("~gravity", "double"), ("~mass", "double")]
    elif where == "header template":
        files = {"simulator_base.hpp": TEMPLATE_HEADER, "main.cpp": TEMPLATE_MAIN}
        expected = [("~gravity", "double"), ("~mass", "double"), ("~rate", "double")]
    else:
        files = {"main.cpp": TEMPLATE_MAIN.replace('#include "simulator_base.hpp"',
                                                   TEMPLATE_HEADER)}
        expected = [("~gravity", "double"), ("~mass", "double"), ("~rate", "double")]
    assert _reads(write_tree, files) == expected
