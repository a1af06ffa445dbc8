"""Whole-workspace C++ extraction through the pipeline: a cold run (every translation
unit parsed, in parallel) against a no-change re-run (everything from the persistent
cache), in this process and as a fresh ``haros-arch extract`` process. Prints the times
and ratios measured in this one run.

    .venv/bin/python bench/cpp_workspace.py [--packages N] [--jobs N] [WORKSPACE ...]

Without WORKSPACE arguments it generates a synthetic catkin workspace of N packages
(default 50; each with a message, two executables and a nodelet that shares a library
source with one of them) in a temporary folder, and adds the fetched real workspaces
found under /tmp/real (ros_tutorials, ros2 demos and examples) when present.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from typing import Any

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

from haros_arch import pipeline  # noqa: E402
from haros_arch.pipeline import Options, analyse  # noqa: E402
from haros_arch.project import load  # noqa: E402

REAL = ["/tmp/real/ros+ros_tutorials", "/tmp/real/ros2+demos", "/tmp/real/ros2+examples"]

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>synthetic package {name}</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>BSD</license>
  <buildtool_depend>catkin</buildtool_depend>
  <depend>roscpp</depend>
  <depend>nodelet</depend>
  <depend>std_msgs</depend>
  <export><nodelet plugin="${{prefix}}/nodelets.xml"/></export>
</package>
"""

CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project({name})
find_package(catkin REQUIRED COMPONENTS roscpp nodelet std_msgs message_generation)
add_message_files(FILES Reading.msg)
generate_messages(DEPENDENCIES std_msgs)
catkin_package()
include_directories(include ${{catkin_INCLUDE_DIRS}})
add_library(${{PROJECT_NAME}}_filter src/filter.cpp src/filter_nodelet.cpp)
add_executable(sensor src/sensor.cpp)
add_executable(filter src/filter_main.cpp)
target_link_libraries(filter ${{PROJECT_NAME}}_filter ${{catkin_LIBRARIES}})
"""

NODELETS = """<library path="lib/lib{name}_filter">
  <class name="{name}/FilterNodelet" type="{name}::FilterNodelet"
         base_class_type="nodelet::Nodelet"><description>filter</description></class>
</library>
"""

FILTER_H = """#pragma once
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <{name}/Reading.h>

namespace {name} {{
class Filter {{
 public:
  Filter(ros::NodeHandle& nh, ros::NodeHandle& pnh);
 private:
  void onReading(const {name}::Reading::ConstPtr& msg);
  ros::Subscriber sub_;
  ros::Publisher pub_;
  double gain_;
}};
}}  // namespace {name}
"""

FILTER_CPP = """#include "{name}/filter.h"

namespace {name} {{
static const char* const kOutput = "filtered";

Filter::Filter(ros::NodeHandle& nh, ros::NodeHandle& pnh) {{
  pnh.param("gain", gain_, 0.5);
  std::string input;
  pnh.param<std::string>("input", input, "reading");
  sub_ = nh.subscribe(input, 10, &Filter::onReading, this);
  pub_ = nh.advertise<std_msgs::Float64>(kOutput, 10);
}}

void Filter::onReading(const {name}::Reading::ConstPtr& msg) {{
  std_msgs::Float64 out;
  out.data = gain_ * msg->value;
  pub_.publish(out);
}}
}}  // namespace {name}
"""

FILTER_NODELET = """#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.h>
#include <boost/shared_ptr.hpp>
#include "{name}/filter.h"

namespace {name} {{
class FilterNodelet : public nodelet::Nodelet {{
 public:
  void onInit() override {{
    filter_.reset(new Filter(getNodeHandle(), getPrivateNodeHandle()));
  }}
 private:
  boost::shared_ptr<Filter> filter_;
}};
}}  // namespace {name}

PLUGINLIB_EXPORT_CLASS({name}::FilterNodelet, nodelet::Nodelet)
"""

FILTER_MAIN = """#include "{name}/filter.h"

int main(int argc, char** argv) {{
  ros::init(argc, argv, "filter");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  {name}::Filter filter(nh, pnh);
  ros::spin();
  return 0;
}}
"""

SENSOR = """#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <{name}/Reading.h>

#define RATE_HZ 20

bool reset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res) {{
  res.success = true;
  return true;
}}

int main(int argc, char** argv) {{
  ros::init(argc, argv, "sensor");
  ros::NodeHandle nh("{name}");
  ros::Publisher pub = nh.advertise<{name}::Reading>("reading", 5);
  ros::ServiceServer srv = nh.advertiseService("reset", reset);
  bool verbose = false;
  nh.getParam("verbose", verbose);
  ros::Rate rate(RATE_HZ);
  while (ros::ok()) {{
    {name}::Reading msg;
    msg.value = 1.0;
    if (verbose) {{
      ROS_INFO("publishing");
    }}
    pub.publish(msg);
    ros::spinOnce();
    rate.sleep();
  }}
  return 0;
}}
"""


def synthetic(folder: str, count: int) -> str:
    """A catkin workspace of ``count`` packages under ``folder``; its project file."""
    for index in range(count):
        name = f"unit{index:03d}"
        pkg = os.path.join(folder, "src", name)
        files = {
            "package.xml": PACKAGE_XML, "CMakeLists.txt": CMAKE, "nodelets.xml": NODELETS,
            "msg/Reading.msg": "Header header\nfloat64 value\n",
            f"include/{name}/filter.h": FILTER_H, "src/filter.cpp": FILTER_CPP,
            "src/filter_nodelet.cpp": FILTER_NODELET, "src/filter_main.cpp": FILTER_MAIN,
            "src/sensor.cpp": SENSOR,
        }
        for rel, text in files.items():
            path = os.path.join(pkg, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(text.format(name=name))
    return project_file(folder, "synthetic")


def project_file(workspace: str, name: str) -> str:
    handle, path = tempfile.mkstemp(prefix=f"{name}-", suffix=".yaml")
    with os.fdopen(handle, "w", encoding="utf-8") as out:
        out.write(f"project: {name}\nworkspace: {workspace}\n")
    return path


STAGE: list[float] = []  # seconds spent in the source-extraction stage, per analyse()


def _timed_stage(real: Callable[..., Any]) -> Callable[..., Any]:
    def stage(*args: Any, **kwargs: Any) -> Any:
        start = time.perf_counter()
        try:
            return real(*args, **kwargs)
        finally:
            STAGE.append(time.perf_counter() - start)
    return stage


def run(label: str, project_path: str, jobs: int | None) -> None:
    project = load(project_path)
    with tempfile.TemporaryDirectory() as store:
        start = time.perf_counter()
        model = analyse(project, options=Options(cache_dir=store, jobs=jobs))
        cold = time.perf_counter() - start
        nodes = [n for p in model.packages for n in p.nodes if n.language == "cpp"]
        units = len({s for n in nodes for s in n.sources})
        calls = sum(len(n.calls) for n in nodes)
        start = time.perf_counter()
        analyse(project, options=Options(cache_dir=store, jobs=jobs))
        warm = time.perf_counter() - start
        env = {**os.environ, "XDG_CACHE_HOME": store}
        command = [sys.executable, "-m", "haros_arch.cli", "extract", project_path, "-q",
                   "-o", os.devnull]
        start = time.perf_counter()
        subprocess.run(command, env=env, check=True, cwd=ROOT)  # fills XDG's folder
        fresh_cold = time.perf_counter() - start
        start = time.perf_counter()
        subprocess.run(command, env=env, check=True, cwd=ROOT)
        fresh_warm = time.perf_counter() - start
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", "import haros_arch.cli, clang.cindex"],
                       check=True, cwd=ROOT)
        startup = time.perf_counter() - start
    print(f"{label}: {len(model.packages)} packages, {len(nodes)} C++ nodes, {units} "
          f"translation units, {calls} calls")
    print(f"  in process, whole pipeline: cold {cold:.2f} s, no-change re-run {warm:.3f} s, "
          f"ratio {cold / warm:.0f}x")
    print(f"  in process, source stage (extract_nodes): cold {STAGE[-2]:.2f} s "
          f"({STAGE[-2] / max(units, 1) * 1000:.1f} ms per unit), no-change re-run "
          f"{STAGE[-1]:.3f} s, ratio {STAGE[-2] / STAGE[-1]:.0f}x")
    print(f"  CLI process: cold {fresh_cold:.2f} s, no-change re-run {fresh_warm:.3f} s "
          f"(of which {startup:.3f} s is Python starting and importing), ratio "
          f"{fresh_cold / fresh_warm:.1f}x")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("workspace", nargs="*")
    parser.add_argument("--packages", type=int, default=50)
    parser.add_argument("--jobs", type=int)
    args = parser.parse_args(argv)
    pipeline.extract_nodes = _timed_stage(pipeline.extract_nodes)  # type: ignore[assignment]
    print(f"{os.cpu_count()} cores; jobs {args.jobs or 'one per core'}")
    if args.workspace:
        for folder in args.workspace:
            run(os.path.basename(folder), project_file(os.path.abspath(folder), "ws"),
                args.jobs)
        return 0
    with tempfile.TemporaryDirectory() as folder:
        run(f"synthetic ({args.packages} packages)", synthetic(folder, args.packages),
            args.jobs)
    for folder in REAL:
        if os.path.isdir(folder):
            run(os.path.basename(folder), project_file(folder, "real"), args.jobs)
    return 0


if __name__ == "__main__":
    checkout.announce()
    sys.exit(main(sys.argv[1:]))
