"""A handle held by reference (``ros::NodeHandle& nodeHandle_``) in a base class whose
constructor, in another file of the node, binds it to its argument; a derived class's
method, in a third file, advertises on it (grid_map_visualization: VisualizationBase.cpp
binds ``nodeHandle_``, PointCloudVisualization.cpp and five other visualizations
advertise on it, the node's ``ros::NodeHandle("~")`` handed down through
GridMapVisualization and VisualizationFactory, each holding it by reference). Only a
handle held by value took what the other file's constructor gives it; by reference the
handle was unknown and the topics ``?/?``. A reference member is bound by every
constructor, so what those constructors give it is what it holds."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """\
#pragma once
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <memory>
class Base {
 public:
  Base(ros::NodeHandle& nodeHandle, const std::string& name);
  virtual ~Base() {}
  virtual bool initialize() = 0;
 protected:
  ros::NodeHandle& nodeHandle_;
  const ros::NodeHandle& constHandle_;
  std::string name_;
  ros::Publisher publisher_;
};
class Points : public Base {
 public:
  Points(ros::NodeHandle& nodeHandle, const std::string& name);
  bool initialize() override;
};
class Factory {
 public:
  explicit Factory(ros::NodeHandle& nodeHandle);
  std::shared_ptr<Base> make(const std::string& name);
 private:
  ros::NodeHandle& nodeHandle_;
};
"""
FILES = {
    "base.cpp": """\
#include "vis/vis.h"
Base::Base(ros::NodeHandle& nodeHandle, const std::string& name)
    : nodeHandle_(nodeHandle), constHandle_(nodeHandle), name_(name) {}
""",
    "points.cpp": """\
#include "vis/vis.h"
Points::Points(ros::NodeHandle& nodeHandle, const std::string& name)
    : Base(nodeHandle, name) {}
bool Points::initialize() {
  publisher_ = nodeHandle_.advertise<std_msgs::String>("points", 1, true);
  double rate = 1.0;
  constHandle_.param("rate", rate, rate);
  return true;
}
""",
    "factory.cpp": """\
#include "vis/vis.h"
Factory::Factory(ros::NodeHandle& nodeHandle) : nodeHandle_(nodeHandle) {}
std::shared_ptr<Base> Factory::make(const std::string& name) {
  return std::shared_ptr<Base>(new Points(nodeHandle_, name));
}
""",
    "node.cpp": """\
#include "vis/vis.h"
int main(int argc, char** argv) {
  ros::init(argc, argv, "vis");
  ros::NodeHandle nodeHandle("~");
  Factory factory(nodeHandle);
  factory.make("cloud")->initialize();
  return 0;
}
"""}


def test_a_reference_handle_member_bound_in_another_file_is_what_it_is_bound_to(
        write_tree) -> None:
    root = write_tree({"vis/package.xml": package_xml("vis", "catkin"),
                       "vis/include/vis/vis.h": HEADER,
                       "vis/CMakeLists.txt": (
                           "cmake_minimum_required(VERSION 3.0.2)\nproject(vis)\n"
                           "find_package(catkin REQUIRED COMPONENTS roscpp std_msgs)\n"
                           "catkin_package()\ninclude_directories(include)\n"
                           "add_executable(vis src/node.cpp src/base.cpp src/points.cpp"
                           " src/factory.cpp)\n"),
                       **{f"vis/src/{name}": text for name, text in FILES.items()}})
    sources = [str(root / "vis" / "src" / name) for name in FILES]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None, jobs=1)
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~points"), ("read", "~rate")]
