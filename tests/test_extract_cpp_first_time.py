"""A lazy initialisation, ``if (!initialized_) { ...; initialized_ = true; }`` (or
``!isInitialized()``, a method returning the member), runs the first time its function
runs: ROS 1 planners' ``initialize`` (dwa_local_planner's, base_local_planner's), which
their host calls once, advertises in such a block. What it makes is made, under no
condition of the ``if``; an ``if (!initialized_)`` that does not set the member (an
early return of a method called before ``initialize``) stays a condition."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
    #include <ros/ros.h>
    #include <std_msgs/String.h>
    #include <string>

    class Planner {
     public:
      Planner() : initialized_(false), ready_(false) {}
      bool isInitialized() { return initialized_; }
      void initialize(const std::string& name) {
        if (!isInitialized()) {
          ros::NodeHandle private_nh("~/" + name);
          plan_ = private_nh.advertise<std_msgs::String>("global_plan", 1);
          initialized_ = true;
        } else {
          again_ = nh_.advertise<std_msgs::String>("again", 1);
        }
        if (!ready_) {
          ready_pub_ = nh_.advertise<std_msgs::String>("ready", 1);
          ready_ = true;
        }
      }
      void compute() {
        if (!initialized_) {
          never_ = nh_.advertise<std_msgs::String>("early", 1);
          return;
        }
        if (!enabled_) {
          off_ = nh_.advertise<std_msgs::String>("off", 1);
          enabled_ = false;
        }
      }
     private:
      ros::NodeHandle nh_;
      bool initialized_, ready_, enabled_;
      ros::Publisher plan_, again_, ready_pub_, never_, off_;
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "planner");
      Planner p;
      p.initialize("dwa");
      p.compute();
      ros::spin();
    }
    """


def test_what_a_lazy_initialisation_makes_is_made(write_tree):
    root = write_tree({
        "src/planner/package.xml": package_xml("planner"),
        "src/planner/CMakeLists.txt": "project(planner)\nadd_executable(n src/n.cpp)\n",
        "src/planner/src/n.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/planner/src/n.cpp")], scan([str(root)]),
                         cache_dir=None)
    calls = sorted((c.name, tuple((k.statement, k.text) for k in c.conditions))
                   for c in result.calls if c.kind == "publish")
    assert calls == [
        ("again", (("else", "!isInitialized()"),)),
        ("early", (("if", "!initialized_"),)),
        # after ``if (!initialized_) {..; return;}``: under its else
        ("off", (("else", "!initialized_"), ("if", "!enabled_"))),
        ("ready", ()),
        ("~dwa/global_plan", ()),
    ]
