"""An object of namespace scope built with arguments passes them to its constructor as
a local does (OpenMower's mower_logic: ``StateSubscriber<mower_msgs::Emergency>
emergency_state_subscriber{"/ll/emergency"};`` beside two more, and ``Start(n)`` in main
subscribes to each one's ``topic_``): one subscription per object's topic, where the
globals gave one subscription to ``?``."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <ros/ros.h>
#include <std_msgs/String.h>
class StateSubscriber {
 public:
  explicit StateSubscriber(const std::string& topic);
  void Start(ros::NodeHandle* n);
 private:
  std::string topic_;
  ros::Subscriber subscriber_;
  void setMessage(const std_msgs::String& m) {}
};
StateSubscriber::StateSubscriber(const std::string& topic) : topic_{topic} {}
void StateSubscriber::Start(ros::NodeHandle* n) {
  subscriber_ = n->subscribe(topic_, 10, &StateSubscriber::setMessage, this);
}
"""

MAIN = """
#include "s/sub.h"
ros::NodeHandle* n;
namespace logic {
StateSubscriber emergency{"/ll/emergency"};
}
StateSubscriber power("/ll/power");
int main(int argc, char** argv) {
  ros::init(argc, argv, "logic");
  n = new ros::NodeHandle();
  logic::emergency.Start(n);
  power.Start(n);
}
"""


@pytest.mark.parametrize("local", [False, True])
def test_a_global_object_passes_its_arguments_to_its_constructor(write_tree,
                                                                 local: bool) -> None:
    main = MAIN
    if local:  # the same objects as locals of main: as before
        main = (MAIN.replace('namespace logic {\nStateSubscriber emergency{"/ll/emergency"};'
                             '\n}\nStateSubscriber power("/ll/power");\n', "")
                .replace("n = new ros::NodeHandle();",
                         'n = new ros::NodeHandle();\n  StateSubscriber emergency{'
                         '"/ll/emergency"};\n  StateSubscriber power("/ll/power");')
                .replace("logic::emergency", "emergency"))
    root = write_tree({
        "s/package.xml": package_xml("s"),
        "s/include/s/sub.h": HEADER,
        "s/src/main.cpp": main,
    })
    result = extract_cpp([str(root / "s" / "src" / "main.cpp")], scan([str(root)]),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.type) for c in result.calls) == [
        ("subscribe", "/ll/emergency", "std_msgs/String"),
        ("subscribe", "/ll/power", "std_msgs/String"),
    ]
