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
#include <ros/ros.h>
namespace drv {
class Driver {
 public:
  virtual ~Driver() {}
  virtual void start(ros::NodeHandle nh) = 0;
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
}
"""

HOST_CPP = """\
#include <ros/ros.h>
#include <host/loader.h>
#include <drv/base.h>
class Chain {
 public:
  Chain(ros::NodeHandle nh) : nh_(nh), loader_("drv", "drv::Driver") {}
  void init() {
    std::string plugin;
    nh_.param("bus/driver_plugin", plugin, std::string("drv/none"));
    driver_ = loader_.createInstance(plugin);
    driver_->start(nh_);
  }
 private:
  ros::NodeHandle nh_;
  host::SafeClassLoader<drv::Driver> loader_;
  std::shared_ptr<drv::Driver> driver_;
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

PLUGINS_XML = """\
<library path="lib/librobot_drv">
  <class name="robot/socket" type="robot::Socket" base_class_type="drv::Driver">
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
                                    "add_library(robot_drv src/socket.cpp)\n",
        "src/robot/src/socket.cpp": ROBOT_CPP,
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
    assert [link.resource.name for link in host.links
            if link.call is not None and link.call.kind == "publish"] == ["/socket_load"]
    # the load hides nothing: the node is not partial for it
    assert host.completeness == "complete", host.completeness_reasons
    assert not [d for d in model.diagnostics + config.diagnostics
                if d.code == "PLUGIN_NOT_FOUND"]
    # the read of the parameter at the load is marked as the load
    assert [(link.call.location.line, link.call.loads) for link in host.links
            if link.call is not None and link.call.kind == "read" and link.call.loads
            and link.resource.name == "/bus/driver_plugin"] == [(10, "pluginlib:drv::Driver")]
