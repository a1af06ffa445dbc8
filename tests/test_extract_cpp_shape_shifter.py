"""topic_tools' ShapeShifter, roscpp's message of any type, when the workspace does not
hold topic_tools (a fallback stand-in): subt 083c6a8's bridge_logger subscribes to the
topics it finds at run time with a ``boost::function<void(const
topic_tools::ShapeShifter::ConstPtr&)>``, which no overload of the permissive
declaration matched (an unresolved subscribe of type ``?`` and a C++ error in the
function, so the node was partial); a relay republishes what it receives with
``msg->advertise(nh, topic, queue, latch)``, a publisher of the type it received (roscpp's
any type, ``topic_tools/ShapeShifter``, which the checks take as any type)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """\
#include <string>
#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>
class Relay {
public:
  Relay() {
    boost::function<void(const topic_tools::ShapeShifter::ConstPtr&)> callback;
    callback = [this](const topic_tools::ShapeShifter::ConstPtr &msg) -> void {
      this->onMessage(msg);
    };
    sub_ = nh_.subscribe("input", 10, callback);
  }
  void onMessage(const topic_tools::ShapeShifter::ConstPtr &msg) {
    if (!advertised_) {
      pub_ = msg->advertise(nh_, "output", 1, true);
      advertised_ = true;
    }
    ROS_INFO("%s", msg->getDataType().c_str());
    pub_.publish(msg);
  }
private:
  ros::NodeHandle nh_;
  ros::Subscriber sub_;
  ros::Publisher pub_;
  bool advertised_ = false;
};
int main(int argc, char **argv) {
  ros::init(argc, argv, "relay");
  Relay relay;
  ros::spin();
}
"""


def test_a_shape_shifter_subscriber_and_its_relay_are_read(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("relay").replace(
        "</package>", "<depend>roscpp</depend><depend>topic_tools</depend></package>"))
    source = tmp_path / "relay.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.code, d.location.line) for d in result.diagnostics] == []
    assert sorted((c.kind, c.name, c.type, c.latch) for c in result.calls) == [
        ("publish", "output", "topic_tools/ShapeShifter", True),
        ("subscribe", "input", "topic_tools/ShapeShifter", False)]
