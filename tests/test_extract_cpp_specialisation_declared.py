"""An explicit specialisation of a member template, declared in its class's header after
``template <>`` (mrs_lib's param_loader.h:1353, ``ros::Duration
ParamLoader::loadParam2<ros::Duration>(const std::string& name, ...);``, defined in
param_loader.cpp), is no call: the recall check's grep of the unit's wrappers took it
for a call site, and with an error elsewhere in the unit said ``CPP_CALL_MISSED`` there
(the node partial for a call that is not there; the header is read for sites where
it holds an error). A call written with the class's name
and template arguments stays a site."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp, recall
from haros_arch.workspace import Workspace

HEADER = """\
#include <string>
#include <ros/ros.h>

class Loader
{
public:
  explicit Loader(ros::NodeHandle& nh) : nh_(nh) {}
  template <typename T>
  T loadParam2(const std::string& name, const T& default_value)
  {
    T value;
    nh_.param(name, value, default_value);
    return value;
  }
  std::string broken(double rate) { return rate * std::string("s"); }
private:
  ros::NodeHandle nh_;
};

template <>
ros::Duration Loader::loadParam2<ros::Duration>(const std::string& name,
                                                const ros::Duration& default_value);
"""

NODE = """\
#include "loader.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "loading");
  ros::NodeHandle nh("~");
  Loader loader(nh);
  double rate = loader.loadParam2<double>("rate", 1.0);
  return 0;
}
"""


def test_a_declared_specialisation_is_no_missed_call(tmp_path: Path) -> None:
    (tmp_path / "loader.h").write_text(HEADER)
    (tmp_path / "node.cpp").write_text(NODE)
    result = extract_cpp([str(tmp_path / "node.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("read", "~rate")]
    assert any(d.code == "CPP_PARSE_ERROR" for d in result.diagnostics)  # sites read
    missed = [(d.location.file, d.location.line) for d in result.diagnostics
              if d.code == "CPP_CALL_MISSED"]
    assert missed == []


def test_a_call_with_template_arguments_stays_a_site() -> None:
    text = ("template <>\n"
            "ros::Duration Loader::loadParam2<ros::Duration>(const std::string& name);\n"
            "std::map<std::string, int> ns::Loader::loadParam2<std::map<std::string, int>>(\n"
            "  return Loader::loadParam2<double>(name);\n"
            "  else Loader::loadParam2<int>(name);\n"
            "  const auto d = loader.loadParam2<ros::Duration>(\"rate\", d0);\n")
    assert [s.line for s in recall.call_sites(text, ["loadParam2"])] == [4, 5, 6]
