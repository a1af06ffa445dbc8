"""A control statement's branches are read once per reading of a unit's function
(``ConditionReader.below``, ``enter``'s ``key``): the walks of a unit read the same
function again (its own calls, then each call site's conditions for the constructions
and arguments it gives), and each read of an ``if`` reads its text, the locals it tests
and the parameters they hold. The conditions are those of a reading that reads anew."""

from __future__ import annotations

from collections import Counter

from haros_arch.extract.cpp import conditions, extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
class Part {
public:
  Part(ros::NodeHandle & nh, const std::string & topic) {
    pub_ = nh.advertise<std_msgs::String>(topic, 1);
  }
  ros::Publisher pub_;
};
class Robot {
public:
  Robot() {
    ros::NodeHandle pnh("~");
    bool fast = false, slow = false;
    pnh.param("fast", fast, false);
    pnh.param("slow", slow, true);
    if (fast) {
      parts_.push_back(new Part(pnh, "fast_out"));
    } else if (slow) {
      parts_.push_back(new Part(pnh, "slow_out"));
    }
    for (int i = 0; i < 2; ++i) {
      if (i == 0) {
        sub_ = pnh.subscribe("first", 1, &Robot::cb, this);
      }
    }
  }
  void cb(const std_msgs::String::ConstPtr &) {}
  std::vector<Part *> parts_;
  ros::Subscriber sub_;
};
int main(int argc, char ** argv) {
  ros::init(argc, argv, "robot");
  Robot robot;
  ros::spin();
}
"""


def _calls(write_tree, monkeypatch, memo: bool):
    root = write_tree({"robot/package.xml": package_xml("robot"),
                       "robot/src/robot.cpp": NODE})
    read: Counter[int] = Counter()
    branches = conditions.ConditionReader.branches
    enter = conditions.ConditionReader.enter

    def counted(self: conditions.ConditionReader, node):  # type: ignore[no-untyped-def]
        read[hash(node)] += 1
        return branches(self, node)

    def anew(self, function, *args, **kwargs):  # type: ignore[no-untyped-def]
        kwargs["key"] = None
        return enter(self, function, *args, **kwargs)

    monkeypatch.setattr(conditions.ConditionReader, "branches", counted)
    if not memo:
        monkeypatch.setattr(conditions.ConditionReader, "enter", anew)
    result = extract_cpp([str(root / "robot" / "src" / "robot.cpp")], scan([str(root)]),
                         cache_dir=None)
    made = sorted((c.kind, c.name, tuple(f"{k.statement} {k.text}" for k in c.conditions))
                  for c in result.calls)
    return made, read


def test_each_statement_is_read_once_and_the_conditions_are_the_same(
        write_tree, monkeypatch) -> None:
    once, read = _calls(write_tree, monkeypatch, memo=True)
    assert read and max(read.values()) == 1, read
    monkeypatch.undo()
    anew, again = _calls(write_tree, monkeypatch, memo=False)
    assert max(again.values()) > 1  # the walks do read the constructor again
    assert once == anew
    # (Part is built under two different tests: the publisher each construction names
    # is under that construction's test alone)
    assert ("publish", "~fast_out", ("if fast",)) in once, once
    assert ("publish", "~slow_out", ("else fast", "if slow")) in once, once
    # (a counting loop over literal bounds runs: only the test inside it is a condition)
    assert ("subscribe", "~first", ("if i == 0",)) in once
