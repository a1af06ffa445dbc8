"""Nodelets of jsk_recognition's kind, built on jsk_common's jsk_topic_tools (installed,
not in the workspace): their base, ``jsk_topic_tools::DiagnosticNodelet``, holds the
handles ``nh_`` / ``pnh_`` and advertises with ``advertise<T>(*pnh_, "output", 1)``.
Without a stand-in each use of ``pnh_`` was an undeclared identifier beside the ROS calls
(221 of jsk_recognition's nodes partial). jsk_topic_tools' ``jsk_nodelet`` (a CMake
function outside the workspace) adds each source to the list its library builds, which
the reading cannot see: each nodelet's node took the library's list of sources itself,
shared, so that every nodelet of jsk_pcl_ros_utils got the other 48's code (69 false
topic-type-mismatch errors once they parsed); a source given to it with a lookup name
the plugin description has since changed (``"jsk_pcl/CloudOnPlane"``) is still the
class's. A class template's dynamic_reconfigure server of its ``Config`` parameter
(jsk_pcl_ros' ColorFilter) serves its parameters."""

from __future__ import annotations

from typing import Any

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

MANIFEST = """<?xml version="1.0"?>
<package format="2"><name>pkg</name><version>0.1.0</version><description>d</description>
  <maintainer email="a@b.c">m</maintainer><license>MIT</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend><depend>nodelet</depend><depend>sensor_msgs</depend>
  <depend>jsk_topic_tools</depend><depend>dynamic_reconfigure</depend>
  <export><nodelet plugin="${prefix}/plugins.xml"/></export>
</package>
"""

PLUGINS = """
    <library path="lib/libpkg">
      <class name="pkg/Relay" type="pkg::Relay" base_class_type="nodelet::Nodelet"/>
      <class name="pkg_utils/Mask" type="pkg::Mask" base_class_type="nodelet::Nodelet"/>
      <class name="pkg/HueFilter" type="pkg::HueFilter" base_class_type="nodelet::Nodelet"/>
    </library>
    """

CMAKE = """
    cmake_minimum_required(VERSION 3.0.2)
    project(pkg)
    find_package(catkin REQUIRED COMPONENTS roscpp nodelet sensor_msgs jsk_topic_tools
                 dynamic_reconfigure)
    catkin_package()
    macro(pkg_nodelet _cpp _cls _bin)
      jsk_nodelet(${_cpp} ${_cls} ${_bin} pkg_nodelet_sources pkg_nodelet_executables)
    endmacro()
    pkg_nodelet(src/relay.cpp "pkg/Relay" "relay")
    pkg_nodelet(src/mask.cpp "pkg_old/Mask" "mask")
    pkg_nodelet(src/hue_filter.cpp "pkg/HueFilter" "hue_filter")
    add_library(pkg SHARED ${pkg_nodelet_sources})
    """

RELAY = """
    #include <jsk_topic_tools/diagnostic_nodelet.h>
    #include <sensor_msgs/Image.h>
    #include <pluginlib/class_list_macros.h>
    namespace pkg {
    class Relay : public jsk_topic_tools::DiagnosticNodelet {
     public:
      Relay() : DiagnosticNodelet("Relay") {}
     protected:
      void onInit() override {
        DiagnosticNodelet::onInit();
        pnh_->param("rate", rate_, 10.0);
        pub_ = advertise<sensor_msgs::Image>(*pnh_, "output", 1);
        onInitPostProcess();
      }
      void subscribe() override { sub_ = pnh_->subscribe("input", 1, &Relay::relay, this); }
      void unsubscribe() override { sub_.shutdown(); }
      void relay(const sensor_msgs::Image::ConstPtr& image) { pub_.publish(image); }
      double rate_;
      ros::Publisher pub_;
      ros::Subscriber sub_;
    };
    }  // namespace pkg
    PLUGINLIB_EXPORT_CLASS (pkg::Relay, nodelet::Nodelet);
    """

MASK = """
    #include <jsk_topic_tools/connection_based_nodelet.h>
    #include <jsk_topic_tools/rosparam_utils.h>
    #include <sensor_msgs/Image.h>
    #include <pluginlib/class_list_macros.h>
    namespace pkg {
    class Mask : public jsk_topic_tools::ConnectionBasedNodelet {
     protected:
      void onInit() override {
        ConnectionBasedNodelet::onInit();
        std::vector<double> bounds;
        jsk_topic_tools::readVectorParameter(*pnh_, "bounds", bounds);
        pub_ = advertise<sensor_msgs::Image>(*pnh_, "mask", 1);
        onInitPostProcess();
      }
      void subscribe() override {}
      void unsubscribe() override {}
      ros::Publisher pub_;
    };
    }  // namespace pkg
    PLUGINLIB_EXPORT_CLASS(pkg::Mask, nodelet::Nodelet);
    """

HUE = """
    #include <jsk_topic_tools/diagnostic_nodelet.h>
    #include <dynamic_reconfigure/server.h>
    #include <sensor_msgs/Image.h>
    #include <pluginlib/class_list_macros.h>
    namespace pkg {
    struct HueConfig { int hue_max; };
    template <class Config>
    class ColorFilter : public jsk_topic_tools::DiagnosticNodelet {
     public:
      ColorFilter() : DiagnosticNodelet("ColorFilter") {}
     protected:
      void onInit() override {
        DiagnosticNodelet::onInit();
        srv_ = boost::make_shared<dynamic_reconfigure::Server<Config> >(*pnh_);
        onInitPostProcess();
      }
      void subscribe() override {}
      void unsubscribe() override {}
      boost::shared_ptr<dynamic_reconfigure::Server<Config> > srv_;
    };
    class HueFilter : public ColorFilter<HueConfig> {};
    }  // namespace pkg
    PLUGINLIB_EXPORT_CLASS(pkg::HueFilter, nodelet::Nodelet);
    """


def test_jsk_nodelets_have_their_own_calls(write_tree: Any) -> None:
    root = write_tree({
        "src/pkg/package.xml": MANIFEST,
        "src/pkg/plugins.xml": PLUGINS,
        "src/pkg/CMakeLists.txt": CMAKE,
        "src/pkg/src/relay.cpp": RELAY,
        "src/pkg/src/mask.cpp": MASK,
        "src/pkg/src/hue_filter.cpp": HUE,
        "project.yaml": "project: p\ndistro: noetic\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    nodes = {n.name: n for p in model.packages for n in p.nodes}
    relay, mask, hue = (nodes[f"pkg/{n}"] for n in ("pkg/Relay", "pkg_utils/Mask",
                                                      "pkg/HueFilter"))
    # each its own file alone, whatever lookup name its CMake call gives it
    assert [s.rsplit("/", 1)[-1] for s in relay.sources] == ["relay.cpp"]
    assert [s.rsplit("/", 1)[-1] for s in mask.sources] == ["mask.cpp"]
    assert [s.rsplit("/", 1)[-1] for s in hue.sources] == ["hue_filter.cpp"]
    for node in (relay, mask, hue):
        assert node.completeness == "complete", (node.name, node.completeness_reasons)
    calls = {(c.kind, c.name, c.type) for c in relay.calls}
    assert {("read", "~rate", "double"), ("publish", "~output", "sensor_msgs/Image"),
            ("subscribe", "~input", "sensor_msgs/Image"), ("read", "~latch", "bool"),
            ("read", "~vital_rate", "double"), ("read", "~always_subscribe", "bool"),
            ("publish", "/diagnostics", "diagnostic_msgs/DiagnosticArray")} <= calls
    # the base's reads have their defaults in its code: none is a required one
    assert all(c.has_default for c in relay.calls if c.kind == "read")
    assert {(c.kind, c.name) for c in mask.calls} >= {
        ("read", "~bounds"), ("publish", "~mask"), ("read", "~always_subscribe")}
    assert not {c.name for c in mask.calls} & {"~output", "~input", "~vital_rate"}
    assert ("server", "~set_parameters") in {(c.kind, c.name) for c in hue.calls}
