"""A getopt option's argument kept as a copy of its text: ``name = std::string(optarg)``,
``std::string{optarg}`` or ``strdup(optarg)`` hold what ``name = optarg`` holds, the
option's value; they stayed ``?`` (no option). A copy of something else, or text made
from optarg (``std::string(optarg) + "/x"``, ``atoi(optarg)``), is not taken."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include <unistd.h>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  ros::init(argc, argv, "copies");
  std::string topic = "chatter";
  std::string frame;
  char* name = NULL;
  std::string other;
  int c;
  while ((c = getopt(argc, argv, "t:f:n:o:")) != -1) {
    switch (c) {
      case 't': topic = std::string(optarg); break;
      case 'f': frame = std::string{optarg}; break;
      case 'n': name = strdup(optarg); break;
      case 'o': other = std::string(optarg) + "_x"; break;
      default: return 1;
    }
  }
  ros::NodeHandle n;
  ros::Publisher a = n.advertise<std_msgs::String>(topic, 1);
  ros::Publisher b = n.advertise<std_msgs::String>(frame + "/frame", 1);
  ros::Publisher d = n.advertise<std_msgs::String>(name, 1);
  ros::Publisher e = n.advertise<std_msgs::String>(other, 1);
  return 0;
}
"""


def test_copies_of_optarg_are_the_option(write_tree) -> None:
    root = write_tree({"src/opt/package.xml": package_xml("opt"),
                       "src/opt/src/copies.cpp": NODE})
    found = extract_cpp([str(root / "src/opt/src/copies.cpp")], scan([str(root)]),
                        cache_dir=None)
    assert not [d for d in found.diagnostics if d.code == "CPP_PARSE_ERROR"]
    assert sorted((c.name, c.name_option or "", c.name_option_default or "")
                  for c in found.calls) == [
        ("?", "-n", ""), ("?", "-t", "chatter"), ("?/frame", "-f", ""), ("?_x", "", "")]
