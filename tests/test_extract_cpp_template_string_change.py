"""A ``std::string`` method that changes the string, called in a class template with an
argument whose type depends on the template's parameters, is a call clang leaves
unresolved (no method, no name): robocup-pkg's robot_comm builds ``std::string name =
"/test/"; name.append(m.name());`` in ``UdpToTopicEntry<T, P>::execute`` (``m`` a
``T&``) and advertises it. The string was read as never changed, ``/test/``, a wrong
known name; the method is now read from the text: ``append`` as ``+=`` (``/test/?``),
any other change (``insert``, ``replace``, ...) leaves the string unknown."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
#include <ros/ros.h>
#include <std_msgs/String.h>
template<class T> struct Entry {
  ros::NodeHandle nh_;
  void execute(const T& m) {
    std::string name = "/test/";
    name.append(m.name());
    ros::Publisher pub = nh_.advertise<std_msgs::String>(name, 1);
    std::string other = "/other";
    other.insert(0, m.prefix());
    ros::Publisher out = nh_.advertise<std_msgs::String>(other, 1);
    std::string kept = "/kept";
    bool found = kept.find(m.name()) != std::string::npos;
    ros::Publisher same = nh_.advertise<std_msgs::String>(kept, 1);
  }
};
struct Message {
  std::string name() const;
  std::string prefix() const;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "relay");
  Entry<Message> e;
  e.execute(Message());
}
"""


def test_a_string_a_template_changes_is_not_kept_as_written(write_tree) -> None:
    root = write_tree({"comm/package.xml": package_xml("comm"),
                       "comm/src/relay.cpp": NODE})
    result = extract_cpp([str(root / "comm" / "src" / "relay.cpp")], scan([str(root)]),
                         cache_dir=None)
    # ``find`` reads the string: it stays known
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "/kept"), ("publish", "/test/?"), ("publish", "?")]
