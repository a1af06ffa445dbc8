"""A pluginlib load through the workspace's own loader class template: ros_canopen's
``GuardedClassLoader<T>`` holds a ``pluginlib::ClassLoader<T>`` and its
``createInstance(lookup_name)`` returns ``loader_->createUniqueInstance(lookup_name)``;
the chain node calls ``driver_loader_.createInstance(driver_plugin)`` with the value of
the parameter ``bus/driver_plugin``. pluginlib's own call with a parameter's value is a
load of the class that parameter names; through the wrapper it was not (the call inside
depends on the template parameter ``T``), so the node stayed partial ("loads plugin
classes by name whose calls are not known here") and the class's calls were not its.
"""

from __future__ import annotations

from conftest import package_xml

from haros_arch.pipeline import analyse
from haros_arch.project import load


def _package(name: str, depends: tuple[str, ...], export: str = "") -> str:
    return package_xml(name).replace(
        "</license>", "</license><buildtool_depend>catkin</buildtool_depend>" + "".join(
            f"<depend>{d}</depend>" for d in depends)).replace(
        "</package>", f"<export>{export}</export></package>" if export else "</package>")


BASE_H = """\
#pragma once
#include <memory>
#include <ros/ros.h>
namespace drv {
class Driver {
 public:
  virtual ~Driver() {}
  virtual void start(ros::NodeHandle nh) = 0;
};
class Master {
 public:
  virtual ~Master() {}
  class Maker {
   public:
    virtual ~Maker() {}
    virtual std::shared_ptr<Master> make(int id) = 0;
  };
};
}
"""

LOADER_H = """\
#pragma once
#include <memory>
#include <string>
#include <pluginlib/class_loader.h>
namespace host {
template<typename T> class SafeClassLoader {
  typedef pluginlib::ClassLoader<T> Loader;
  std::shared_ptr<Loader> loader_;
 public:
  typedef std::shared_ptr<T> ClassPtr;
  SafeClassLoader(const std::string& package, const std::string& base)
  : loader_(new Loader(package, base)) {}
  ClassPtr createInstance(const std::string& lookup_name) {
    return loader_->createUniqueInstance(lookup_name);
  }
};
template<typename T> class Allocating : public SafeClassLoader<typename T::Maker> {
 public:
  Allocating(const std::string& package, const std::string& base)
  : SafeClassLoader<typename T::Maker>(package, base) {}
  template<typename A> std::shared_ptr<T> allocate(const std::string& lookup_name, const A& a) {
    return this->createInstance(lookup_name)->make(a);
  }
};
}
"""

HOST_CPP = """\
#include <ros/ros.h>
#include <host/loader.h>
#include <drv/base.h>
class Chain {
 public:
  Chain(ros::NodeHandle nh)
  : nh_(nh), loader_("drv", "drv::Driver"), masters_("drv", "drv::Master::Maker") {}
  void init() {
    std::string plugin;
    nh_.param("bus/driver_plugin", plugin, std::string("drv/none"));
    driver_ = loader_.createInstance(plugin);
    driver_->start(nh_);
    std::string maker;
    nh_.param("bus/master", maker, std::string("robot::Simple::Maker"));
    master_ = masters_.allocate(maker, 3);
  }
 private:
  ros::NodeHandle nh_;
  host::SafeClassLoader<drv::Driver> loader_;
  std::shared_ptr<drv::Driver> driver_;
  host::Allocating<drv::Master> masters_;
  std::shared_ptr<drv::Master> master_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "host");
  ros::NodeHandle nh;
  Chain chain(nh);
  chain.init();
  ros::spin();
}
"""

ROBOT_CPP = """\
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <pluginlib/class_list_macros.h>
#include <drv/base.h>
namespace robot {
class Socket : public drv::Driver {
 public:
  void start(ros::NodeHandle nh) override {
    pub_ = nh.advertise<std_msgs::Float64>("socket_load", 1);
  }
 private:
  ros::Publisher pub_;
};
}
PLUGINLIB_EXPORT_CLASS(robot::Socket, drv::Driver)
"""

MASTER_CPP = """\
#include <memory>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <pluginlib/class_list_macros.h>
#include <drv/base.h>
namespace robot {
class Simple : public drv::Master {
 public:
  class Maker : public drv::Master::Maker {
   public:
    std::shared_ptr<drv::Master> make(int id) override {
      ros::NodeHandle nh;
      pub_ = nh.advertise<std_msgs::Float64>("master_load", 1);
      return std::make_shared<Simple>();
    }
   private:
    ros::Publisher pub_;
  };
};
}
PLUGINLIB_EXPORT_CLASS(robot::Simple::Maker, drv::Master::Maker)
"""

PLUGINS_XML = """\
<library path="lib/librobot_drv">
  <class name="robot/socket" type="robot::Socket" base_class_type="drv::Driver">
    <description>d</description>
  </class>
  <class type="robot::Simple::Maker" base_class_type="drv::Master::Maker">
    <description>d</description>
  </class>
</library>
"""

LAUNCH = """\
<launch>
  <param name="bus/driver_plugin" value="robot/socket" />
  <node pkg="host" type="host_node" name="host" />
</launch>
"""


def _tree(write_tree):  # type: ignore[no-untyped-def]
    return write_tree({
        "src/drv/package.xml": _package("drv", ("roscpp",)),
        "src/drv/CMakeLists.txt": "project(drv)\nfind_package(catkin REQUIRED)\n"
                                  "catkin_package(INCLUDE_DIRS include)\n",
        "src/drv/include/drv/base.h": BASE_H,
        "src/host/package.xml": _package("host", ("roscpp", "pluginlib", "drv")),
        "src/host/CMakeLists.txt": "project(host)\nfind_package(catkin REQUIRED)\n"
                                   "catkin_package(INCLUDE_DIRS include)\n"
                                   "add_executable(host_node src/host_node.cpp)\n",
        "src/host/include/host/loader.h": LOADER_H,
        "src/host/src/host_node.cpp": HOST_CPP,
        "src/host/launch/run.launch": LAUNCH,
        "src/robot/package.xml": _package("robot", ("roscpp", "pluginlib", "drv"),
                                          '<drv plugin="${prefix}/plugins.xml"/>'),
        "src/robot/CMakeLists.txt": "project(robot)\nfind_package(catkin REQUIRED)\n"
                                    "catkin_package()\n"
                                    "add_library(robot_drv src/socket.cpp src/master.cpp)\n",
        "src/robot/src/socket.cpp": ROBOT_CPP,
        "src/robot/src/master.cpp": MASTER_CPP,
        "src/robot/plugins.xml": PLUGINS_XML,
        "project.yaml": "project: p\nconfigurations:\n  c: [host/launch/run.launch]\n",
    })


def test_a_load_through_a_loader_class_template_loads_the_parameters_class(
        write_tree) -> None:
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    (host,) = config.nodes
    # the class the parameter names is loaded into the host: its publisher is the host's
    assert "/socket_load" in [link.resource.name for link in host.links
                              if link.call is not None and link.call.kind == "publish"]
    # the load hides nothing: the node is not partial for it
    assert host.completeness == "complete", host.completeness_reasons
    assert not [d for d in model.diagnostics + config.diagnostics
                if d.code == "PLUGIN_NOT_FOUND"]
    # the read of the parameter at the load is marked as the load
    assert [(link.call.location.line, link.call.loads) for link in host.links
            if link.call is not None and link.call.kind == "read" and link.call.loads
            and link.resource.name == "/bus/driver_plugin"] == [(11, "pluginlib:drv::Driver")]


def test_a_load_in_a_template_on_the_class_its_use_gives_loads_the_parameters_class(
        write_tree) -> None:
    """ros_canopen's ClassAllocator<T> (a GuardedClassLoader<typename T::Allocator>):
    ``allocateInstance(name, a)`` returns ``this->createInstance(name)->allocate(a)``,
    no instance of the loaded class: the load is read where it is made, named through
    the callers, its base not known there (the template's ``T::Allocator``). The class
    the parameter's default names is loaded (it was not: no plugin class of that base
    is a node unless a load names its base, PLUGIN_NOT_FOUND)."""
    root = _tree(write_tree)
    model = analyse(load(str(root / "project.yaml")), {"PATH": ""})
    (config,) = model.configurations
    (host,) = config.nodes
    assert "/master_load" in [link.resource.name for link in host.links
                              if link.call is not None and link.call.kind == "publish"]
    assert [link.call.loads for link in host.links
            if link.call is not None and link.call.kind == "read" and link.call.loads
            and link.resource.name == "/bus/master"] == ["pluginlib"]
