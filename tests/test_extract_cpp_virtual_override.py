"""A call of a virtual method through a base class (``boost::shared_ptr<Analyzer>
group; group->init(base, ros::NodeHandle(ns))``) may run any override: what it passes
is passed to the overrides defined in the node's other files too, not only what their
direct callers pass. diagnostic_aggregator (noetic): ``Aggregator`` calls
``AnalyzerGroup::init`` with its ``~`` handle (aggregator.cpp:60) and, through
``Analyzer::init``, with the namespace an ``add_diagnostics`` request names
(aggregator.cpp:188); an AnalyzerGroup calls ``init`` of its children through the base
class with ``NodeHandle(n, "analyzers/<name>")`` (analyzer_group.cpp:140), a chain of
any depth: unknown."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

BASE = """#include <ros/ros.h>
#include <string>
class Analyzer {
 public:
  virtual ~Analyzer() {}
  virtual bool init(const std::string base, const ros::NodeHandle& n) = 0;
};
class Group : public Analyzer {
 public:
  bool init(const std::string base, const ros::NodeHandle& n) override;
 private:
  std::vector<boost::shared_ptr<Analyzer>> children_;
};
class Leaf : public Analyzer {
 public:
  bool init(const std::string base, const ros::NodeHandle& n) override;
};
"""

GROUP = """#include "agg/analyzer.h"
bool Group::init(const std::string base, const ros::NodeHandle& n) {
  std::string path;
  n.param("path", path, std::string(""));
  ros::NodeHandle below(n, "analyzers");
  for (size_t i = 0; i < children_.size(); ++i) {
    children_[i]->init(path, ros::NodeHandle(below, "child"));
  }
  return true;
}
bool Leaf::init(const std::string base, const ros::NodeHandle& n) {
  double timeout;
  n.param("timeout", timeout, 5.0);
  return true;
}
"""

MAIN = """#include <boost/shared_ptr.hpp>
#include <std_srvs/Trigger.h>
#include "agg/analyzer.h"
class Aggregator {
 public:
  Aggregator() {
    ros::NodeHandle pnh("~");
    group_ = new Group();
    group_->init("", pnh);
    srv_ = pnh.advertiseService("/add", &Aggregator::add, this);
  }
  bool add(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res) {
    boost::shared_ptr<Analyzer> group(new Group());
    return group->init("", ros::NodeHandle(res.message));
  }
  Group* group_;
  ros::ServiceServer srv_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "aggregator");
  Aggregator agg;
  ros::spin();
}
"""


def test_a_call_through_the_base_class_reaches_the_override(tmp_path: Path) -> None:
    package = tmp_path / "src" / "agg"
    (package / "src").mkdir(parents=True)
    (package / "include" / "agg").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>agg</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend></package>\n')
    (package / "include" / "agg" / "analyzer.h").write_text(BASE)
    (package / "src" / "group.cpp").write_text(GROUP)
    (package / "src" / "main.cpp").write_text(MAIN)
    src = package / "src"
    batch = extract_cpp_nodes([[str(src / "main.cpp"), str(src / "group.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    reads = sorted(c.name for c in batch.results[0].calls if c.kind == "read")
    # the group: its direct caller's ~, the request's namespace, not known; a leaf only
    # through the base class: under a group's analyzers (~ or unknown), or the request's
    assert reads == ["?/analyzers/child/timeout", "?/path", "?/timeout",
                     "~analyzers/child/timeout", "~path"]
