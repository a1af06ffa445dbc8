"""A topic named by a parameter's value that a method passes on to a constructor, called
with the values of several parameters: f1tenth_simulator's mux (mux.cpp:106-136, 247-251)
reads ``rand_drive_topic``, ``brake_drive_topic`` and ``nav_drive_topic`` and calls
``add_channel(topic, ...)`` with each, which builds ``new Channel(channel_name, ...)``,
whose constructor subscribes to ``channel_name``. One subscription per parameter; before,
the calls of ``add_channel`` "agreed" (each passes a string not known statically), so the
constructor's name was one ``?`` naming no parameter (a third call passing another value
made them disagree, and each was kept)."""

from __future__ import annotations

from pathlib import Path

from haros_arch.extract.cpp import extract_cpp_nodes
from haros_arch.workspace import scan

SOURCE = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Mux;
class Channel {
public:
  Channel(std::string channel_name, Mux* mux);
  void cb(const std_msgs::String& msg) {}
  ros::Subscriber sub;
};
class Mux {
public:
  ros::NodeHandle n;
  friend class Channel;
  Mux() : n("~") {
    std::string rand_topic;
    n.getParam("rand_drive_topic", rand_topic);
    add_channel(rand_topic);
    std::string brake_topic;
    n.getParam("brake_drive_topic", brake_topic);
    add_channel(brake_topic);
  }
  void add_channel(std::string channel_name) {
    Channel* channel = new Channel(channel_name, this);
  }
};
Channel::Channel(std::string channel_name, Mux* mux) {
  sub = mux->n.subscribe(channel_name, 1, &Channel::cb, this);
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "mux");
  Mux m;
  ros::spin();
}
"""


def _subscriptions(tmp_path: Path, source: str) -> list[tuple[str, str | None]]:
    package = tmp_path / "mux"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>mux</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend><depend>std_msgs</depend></package>\n')
    (package / "src" / "mux.cpp").write_text(source)
    batch = extract_cpp_nodes([[str(package / "src" / "mux.cpp")]], scan([str(tmp_path)]),
                              cache_dir=None, jobs=1)
    return sorted((c.name, c.name_param) for c in batch.results[0].calls
                  if c.kind == "subscribe")


def test_each_parameter_a_method_passes_on_names_a_subscription(tmp_path: Path) -> None:
    assert _subscriptions(tmp_path, SOURCE) == [
        ("~?", "~brake_drive_topic"), ("~?", "~rand_drive_topic")]


def test_callers_that_agree_on_a_known_name_still_give_it(tmp_path: Path) -> None:
    # the values the calls pass, when they are known and the same, are the one value
    source = SOURCE.replace("add_channel(rand_topic);", 'add_channel("drive");').replace(
        "add_channel(brake_topic);", 'add_channel("drive");')
    assert _subscriptions(tmp_path, source) == [("~drive", None)]


# f1tenth's Channel also has ``Channel::Channel() { Channel("", "", -1, nullptr); }``
# (mux.cpp:242-245): a default constructor nothing calls, which would pass "" to the
# one that subscribes, a subscription to the node's own name (``~``), /mux_controller
DEFAULT = SOURCE.replace(
    "  Channel(std::string channel_name, Mux* mux);",
    "  Channel();\n  Channel(std::string channel_name, Mux* mux);").replace(
    "Channel::Channel(std::string channel_name, Mux* mux) {",
    'Channel::Channel() {\n  Channel("", nullptr);\n}\n'
    "Channel::Channel(std::string channel_name, Mux* mux) {")


def test_a_constructor_nothing_calls_passes_no_name(tmp_path: Path) -> None:
    assert _subscriptions(tmp_path, DEFAULT) == [
        ("~?", "~brake_drive_topic"), ("~?", "~rand_drive_topic")]


def test_a_default_constructor_the_node_calls_passes_its_name(tmp_path: Path) -> None:
    source = DEFAULT.replace("  Mux m;\n", "  Mux m;\n  Channel unnamed;\n")
    assert _subscriptions(tmp_path, source) == [
        ("~", None), ("~?", "~brake_drive_topic"), ("~?", "~rand_drive_topic")]


# nav2's velocity smoother builds its OdomSmoother with the member ``odom_topic_`` at
# three places (velocity_smoother.cpp:71, 602, 625): the same member each time is one
# value, the parameter with its default (``odom``), not one value per call
SAME_MEMBER = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Channel {
public:
  Channel(ros::NodeHandle& n, std::string name) { sub = n.subscribe(name, 1, &Channel::cb, this); }
  void cb(const std_msgs::String& msg) {}
  ros::Subscriber sub;
};
class Smoother {
public:
  ros::NodeHandle n;
  std::string topic_;
  Channel* channel;
  Smoother() : n("~") {
    n.param("odom_topic", topic_, std::string("odom"));
    channel = new Channel(n, topic_);
  }
  void reset() { channel = new Channel(n, topic_); }
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "smoother");
  Smoother s;
  s.reset();
  ros::spin();
}
"""


def test_the_same_member_passed_by_each_call_is_one_value(tmp_path: Path) -> None:
    package = tmp_path / "smoother"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>smoother</name><version>1.0.0</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license><depend>roscpp</depend><depend>std_msgs</depend></package>\n')
    (package / "src" / "smoother.cpp").write_text(SAME_MEMBER)
    batch = extract_cpp_nodes([[str(package / "src" / "smoother.cpp")]],
                              scan([str(tmp_path)]), cache_dir=None, jobs=1)
    assert [(c.name, c.name_param, c.name_default) for c in batch.results[0].calls
            if c.kind == "subscribe"] == [("~?", "~odom_topic", "odom")]
