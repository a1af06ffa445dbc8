"""A member of a message known only by name, in a unit that uses the message without
including it (a missing header of another package would have: ``_unincluded_messages``
includes the message's header for it, ahead of the unit).

Autoware's multi_object_tracker (1de8fc5b^, autoware_auto_perception_msgs not in the
workspace) fills its tracker map with ``std::make_pair(Label::CAR,
this->declare_parameter<std::string>("car_tracker"))``. The synthesised names declare
``CAR`` through a macro the message's struct expands; the header defining it was
included after the message's, so the struct never saw it: ``Label::CAR`` stayed an
error and the seven declarations beside it were lost (the node partial, its parameter
file's misspelt ``diagnostic_warn_delay`` undecided)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <vendor_utils/objects.hpp>
#include <map>
#include <string>
#include <utility>
using Label = vendor_msgs::msg::ObjectClassification;
class Tracker : public rclcpp::Node {
 public:
  Tracker() : Node("tracker") {
    trackers_.insert(
      std::make_pair(Label::CAR, this->declare_parameter<std::string>("car_tracker")));
    trackers_.insert(
      std::make_pair(Label::BUS, this->declare_parameter<std::string>("bus_tracker")));
    delay_ = this->declare_parameter<double>("diagnostics_warn_delay");
  }
  std::map<std::uint8_t, std::string> trackers_;
  double delay_;
};
"""


def test_a_member_of_a_message_the_unit_does_not_include(tmp_path) -> None:
    deps = "<depend>rclcpp</depend><depend>vendor_msgs</depend></package>"
    (tmp_path / "vendor_msgs").mkdir()
    (tmp_path / "vendor_msgs/package.xml").write_text(package_xml("vendor_msgs",
                                                                  "ament_cmake"))
    (tmp_path / "tracker").mkdir()
    (tmp_path / "tracker/package.xml").write_text(
        package_xml("tracker", "ament_cmake").replace("</package>", deps))
    source = tmp_path / "tracker/tracker.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [
        ("declare", "car_tracker"), ("declare", "bus_tracker"),
        ("declare", "diagnostics_warn_delay")]
    said = {d.code: d.message for d in result.diagnostics}
    assert "CPP_MESSAGE_UNKNOWN" in said  # the message is known by name only
    assert "vendor_msgs::msg::ObjectClassification::BUS" in said["CPP_NAMES_DECLARED"]
    assert "CPP_ERROR_NEAR_CALL" not in said and "CPP_MESSAGE_FIELD" not in said
