"""A ROS call clang finds ambiguous, kept by its name (``CPP_CALL_UNRESOLVED``), is in
the model: clang's error about that call hides no other, so the node is not partial for
it. An error beside it that names another call still is."""

from __future__ import annotations

from pathlib import Path

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

# cob_navigation 42c9280's cob_linear_nav: a service of cob_srvs, a package not in the
# workspace, so its request's ``data`` is of a type the parse does not know, and
# setParam(std::string, T) has several overloads it converts to
NAV = """
#include <ros/ros.h>
#include <cob_srvs/SetString.h>

class LinearNav {
 public:
  LinearNav() {
    server_ = nh_.advertiseService("set_global_frame", &LinearNav::serviceCB, this);
  }
  bool serviceCB(cob_srvs::SetString::Request &req, cob_srvs::SetString::Response &res) {
    global_frame_ = req.data;
    ros::NodeHandle private_nh("~");
    private_nh.setParam("global_frame", req.data);
    res.success = true;
    return true;
  }
  bool otherCB(cob_srvs::SetString::Request &req, cob_srvs::SetString::Response &res) {
    ros::NodeHandle private_nh("~");
    private_nh.setParam("robot_frame", req.data);
    undeclared_helper(private_nh);
    return true;
  }
  ros::NodeHandle nh_;
  ros::ServiceServer server_;
  std::string global_frame_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "cob_linear_nav");
  LinearNav nav;
  ros::spin();
  return 0;
}
"""


def _extract(tmp_path: Path, text: str):
    package = tmp_path / "src" / "nav"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(package_xml("nav"))
    (package / "src" / "nav.cpp").write_text(text)
    return extract_cpp([str(package / "src" / "nav.cpp")], scan([str(tmp_path / "src")]),
                       cache_dir=None)


def test_an_ambiguous_call_kept_by_its_name_hides_nothing(tmp_path: Path) -> None:
    first = NAV.split("  bool otherCB")[0] + NAV.split("    return true;\n  }\n")[-1]
    result = _extract(tmp_path, first)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("server", "set_global_frame"), ("write", "~global_frame")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_CALL_UNRESOLVED" in codes
    assert "CPP_ERROR_NEAR_CALL" not in codes, result.diagnostics


def test_another_error_beside_it_still_may_hide_a_call(tmp_path: Path) -> None:
    result = _extract(tmp_path, NAV)
    # (the unknown helper, called in a method of a class without bases, is declared
    # at namespace scope: the parse reads the call, and says the node is given to it)
    near = [d for d in result.diagnostics
            if d.code in ("CPP_ERROR_NEAR_CALL", "CPP_NODE_TO_UNKNOWN")]
    assert [d.location.line for d in near] == [NAV.splitlines().index(
        "    undeclared_helper(private_nh);") + 1], near


# scan_tools 219c319's laser_scan_matcher: ``getParam("epsilon_xy", input_.epsilon_xy)``
# into the fields of ``sm_params``, a struct of csm, whose header the workspace lacks
MATCHER = """
#include <ros/ros.h>
#include <csm/csm_all.h>

class Matcher {
 public:
  explicit Matcher(ros::NodeHandle nh_private) : nh_private_(nh_private) {
    if (!nh_private_.getParam("max_iterations", input_.max_iterations))
      input_.max_iterations = 10;
    if (!nh_private_.getParam("epsilon_xy", input_.epsilon_xy))
      input_.epsilon_xy = 0.000001;
    nh_private_.param("publish_tf", publish_tf_, true);
  }
 private:
  ros::NodeHandle nh_private_;
  sm_params input_;
  sm_result output_;
  bool publish_tf_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "matcher");
  Matcher matcher(ros::NodeHandle("~"));
  ros::spin();
}
"""


def test_the_parse_that_keeps_calls_by_name_is_chosen(tmp_path: Path) -> None:
    """Declared permissively, ``sm_params``' fields make each ``getParam`` ambiguous to
    clang (more errors than the parse without them, where ``sm_params`` is an unknown
    type and every such statement is lost): the walk keeps those calls by name, so
    that parse is the better one."""
    result = _extract(tmp_path, MATCHER)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("read", "~epsilon_xy"), ("read", "~max_iterations"), ("read", "~publish_tf")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_NAMES_DECLARED" in codes
    assert "CPP_CALL_MISSED" not in codes and "CPP_ERROR_NEAR_CALL" not in codes, \
        result.diagnostics
