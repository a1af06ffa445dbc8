"""roscpp's ``ros::names::resolve(name)`` in a topic name (imu_tools' filters:
``ros::names::resolve("imu") + "/data"``): the name resolved in the node's namespace,
whatever the handle's, and remapped there, then the rest within it."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

FILTER = """\
#include <ros/ros.h>
#include <sensor_msgs/Imu.h>

class Filter {
 public:
  Filter(const ros::NodeHandle& nh, const ros::NodeHandle& pnh) : nh_(nh), pnh_(pnh) {
    pub_ = nh_.advertise<sensor_msgs::Imu>(ros::names::resolve("imu") + "/data", 5);
    std::string raw = ros::names::resolve("imu") + "/data_raw";
    sub_ = pnh_.subscribe(raw, 5, &Filter::onImu, this);
    ros::NodeHandle ns(nh_, "debug");
    dbg_ = ns.advertise<sensor_msgs::Imu>(ros::names::resolve("imu"), 1);
  }
  void onImu(const sensor_msgs::Imu::ConstPtr& msg) {}
 private:
  ros::NodeHandle nh_, pnh_;
  ros::Publisher pub_, dbg_;
  ros::Subscriber sub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "imu_filter");
  Filter filter(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
}
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.0.2)
project(imu)
find_package(catkin REQUIRED COMPONENTS roscpp sensor_msgs)
catkin_package()
add_executable(filter src/filter.cpp)
"""


def _links(write_tree, remaps: str) -> list[tuple[str, str]]:
    root = write_tree({
        "src/imu/package.xml": package_xml("imu"),
        "src/imu/CMakeLists.txt": CMAKE,
        "src/imu/src/filter.cpp": FILTER,
        "src/imu/launch/filter.launch": (
            '<launch><group ns="robot"><node pkg="imu" type="filter" name="filter">'
            f"{remaps}</node></group></launch>\n"),
        "project.yaml": "project: p\nconfigurations:\n  c: [imu/launch/filter.launch]\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    (config,) = model.configurations
    (node,) = [n for n in config.nodes if n.name == "/robot/filter"]
    return sorted((link.kind, link.rosname.full) for link in node.links
                  if link.kind in ("publish", "subscribe"))


def test_a_resolved_prefix_is_in_the_node_namespace(write_tree):
    # the private handle (~) and the handle "debug" do not move the resolved names
    assert _links(write_tree, "") == [
        ("publish", "/robot/imu"), ("publish", "/robot/imu/data"),
        ("subscribe", "/robot/imu/data_raw")]


def test_a_remap_of_the_prefix_or_of_the_whole_name_applies(write_tree):
    assert _links(write_tree, '<remap from="imu" to="imu0"/>'
                              '<remap from="imu/data_raw" to="/raw"/>') == [
        ("publish", "/robot/imu0"), ("publish", "/robot/imu0/data"),
        ("subscribe", "/robot/imu0/data_raw")]
    assert _links(write_tree, '<remap from="imu/data_raw" to="/raw"/>') == [
        ("publish", "/robot/imu"), ("publish", "/robot/imu/data"),
        ("subscribe", "/raw")]
