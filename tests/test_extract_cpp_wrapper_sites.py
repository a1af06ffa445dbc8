"""The recall check's call sites of a unit's own wrappers (``recall.call_sites``): a
wrapper named like a common method (nav2_smac_planner's ``SearchInfo::get(node, name)``,
which reads parameters) is not called by every ``ptr.get()`` or ``std::get<I>(t)`` of
the unit's files. A call with no argument is a site only of a wrapper that can be
called so (a default for each parameter), and a call written in ``std::`` never is."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

NODE = """\
#include <memory>
#include <string>
#include <tuple>
#include <rclcpp/rclcpp.hpp>

struct Info {
  double rate{0.0};
  void get(rclcpp::Node * node, const std::string & name)
  {
    rate = node->declare_parameter(name + ".rate", 1.0);
  }
};

struct Limits {
  int most{0};
  void load(rclcpp::Node * node = nullptr, const std::string & name = "limits")
  {
    most = node->declare_parameter(name + ".most", 3);
  }
};

int helper(std::shared_ptr<int> ptr, std::tuple<int, int> pair)
{
  int * raw = ptr.get();
  int first = std::get<0>(pair);
  undeclared_thing();
  return *raw + first;
}

class Planner : public rclcpp::Node
{
public:
  Planner() : Node("planner")
  {
    info_.get(this, "search");
    limits_.load(this, "limits");
  }
  Info info_;
  Limits limits_;
};
"""


def test_common_method_names_of_wrappers_are_not_missed_calls(tmp_path: Path) -> None:
    (tmp_path / "n.cpp").write_text(NODE)
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "limits.most"), ("declare", "search.rate")]
    assert any(d.code == "CPP_PARSE_ERROR" for d in result.diagnostics)  # read for sites
    # ptr.get() and std::get<0>(pair) call no wrapper: no call site is missed, and the
    # error in helper() is not in a function that calls the ROS API
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL")] == []


def test_a_wrapper_called_with_no_argument_is_still_a_site(tmp_path: Path) -> None:
    """A call with no argument of a wrapper whose every parameter has a default
    (``load(node = nullptr, name = "limits")``) stays a site: missed where the parse
    extracted nothing (an object of a type it does not know); one of ``get``, which
    needs its arguments, is not."""
    text = NODE.replace("  int * raw = ptr.get();\n",
                        "  int * raw = ptr.get();\n  unknown_limits.load();\n"
                        "  unknown_info.get();\n")
    (tmp_path / "n.cpp").write_text(text)
    result = extract_cpp([str(tmp_path / "n.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    # the site makes the error beside it one that may hide a call (the node partial)
    assert any(d.code in ("CPP_CALL_MISSED", "CPP_ERROR_NEAR_CALL") and d.location.line == 25
               for d in result.diagnostics)
    assert not any(d.code == "CPP_CALL_MISSED" and d.location.line == 26
                   for d in result.diagnostics)
