"""A name written around a parameter's value into a string stream, or kept in a member
a constructor builds from it, names the call by that parameter, as a concatenation in
the call does. mas_industrial_robotics' pddl_problem_generator.cpp:4-37 reads
``knowledge_base`` (default ``rosplan_knowledge_base``), writes ``ss << "/" <<
knowledge_base << "/domain/name"`` and keeps ``ss.str()`` in a member, which another
method gives ``serviceClient``: its six clients stayed ``/?/domain/name``, ... (survey
surveyB). A stream written twice with no emptying between, or a member built from two
parameters' values, is no one parameter's."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <sstream>
#include <string>
class Generator {
 public:
  Generator() : nh_("~") {
    std::string kb;
    nh_.param<std::string>("knowledge_base", kb, "rosplan_knowledge_base");
    std::string other;
    nh_.param<std::string>("other", other, "x");
    std::stringstream ss;
    ss << "/" << kb << "/domain/name";
    name_srv_ = ss.str();
    ss.str("");
    ss << "/" << kb << "/" << other << "/both";
    both_srv_ = ss.str();
    plain_srv_ = "/" + kb + "/plain";
  }
  void run() {
    ros::ServiceClient a = nh_.serviceClient<std_srvs::Empty>(name_srv_);
    ros::ServiceClient b = nh_.serviceClient<std_srvs::Empty>(plain_srv_);
    ros::ServiceClient c = nh_.serviceClient<std_srvs::Empty>(both_srv_);
  }
 private:
  ros::NodeHandle nh_;
  std::string name_srv_, plain_srv_, both_srv_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "generator");
  ros::NodeHandle nh("~");
  std::string kb;
  nh.param<std::string>("kb", kb, "base");
  std::ostringstream out;
  out << kb << "/state";
  ros::ServiceClient d = nh.serviceClient<std_srvs::Empty>(out.str());
  Generator g;
  g.run();
  ros::spin();
}
"""


def test_a_stream_or_a_member_around_a_parameter_value_names_its_call(write_tree) -> None:
    root = write_tree({"gen/package.xml": package_xml("gen"), "gen/src/node.cpp": NODE})
    result = extract_cpp([str(root / "gen" / "src" / "node.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.name, c.name_param, c.name_default) for c in result.calls
                   if c.kind == "client")
    assert calls == [
        ("/?/?/both", "~knowledge_base", "rosplan_knowledge_base"),
        ("/?/domain/name", "~knowledge_base", "rosplan_knowledge_base"),
        ("/?/plain", "~knowledge_base", "rosplan_knowledge_base"),
        ("~?/state", "~kb", "base"),  # on the private handle
    ]
