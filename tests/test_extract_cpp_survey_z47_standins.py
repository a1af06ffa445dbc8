"""Stand-in gaps Autoware.AI's nodes met (survey Z47), each an error in a function
that makes ROS calls, so the node was partial:

- Eigen: a translation times an angle-axis rotation is an affine transform
  (lidar_localizer's ndt_matching_tku, ndt_mapping_tku, icp_matching and
  approximate_ndt_mapping: ``(init_translation * init_rotation_z * ...).matrix()``);
- message_filters: ``Synchronizer::getPolicy()`` (lane_planner's lane_select);
- std::function: a lambda converts only to the std::function types whose arguments it
  takes, so overloads on several (vector_map's ``findByFilter(const Filter<T>&)`` for
  every map type) are not ambiguous (decision_maker's ``initVectorMap``)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NDT = """#include <ros/ros.h>
#include <std_msgs/Float32.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

int main(int argc, char** argv) {
  ros::init(argc, argv, "ndt");
  ros::NodeHandle nh, pnh("~");
  float x = pnh.param<float>("x", 0.0f);
  Eigen::Translation3f translation(x, 0.0f, 0.0f);
  Eigen::AngleAxisf rz(0.5f, Eigen::Vector3f::UnitZ());
  Eigen::AngleAxisf ry(0.0f, Eigen::Vector3f::UnitY());
  Eigen::Matrix4f guess = (translation * rz * ry).matrix();
  ros::Publisher pub = nh.advertise<std_msgs::Float32>("ndt_reliability", 10);
  ros::spin();
}
"""

SYNC = """#include <ros/ros.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <message_filters/subscriber.h>
#include <message_filters/synchronizer.h>
#include <message_filters/sync_policies/approximate_time.h>
#include <memory>

typedef message_filters::sync_policies::ApproximateTime<geometry_msgs::PoseStamped,
                                                        geometry_msgs::TwistStamped> Policy;
typedef message_filters::Synchronizer<Policy> Sync;

void both(const geometry_msgs::PoseStampedConstPtr& p,
          const geometry_msgs::TwistStampedConstPtr& t) {}

int main(int argc, char** argv) {
  ros::init(argc, argv, "lane_select");
  ros::NodeHandle nh;
  message_filters::Subscriber<geometry_msgs::PoseStamped> pose(nh, "current_pose", 1);
  message_filters::Subscriber<geometry_msgs::TwistStamped> twist(nh, "current_velocity", 1);
  std::shared_ptr<Sync> sync(new Sync(Policy(10), pose, twist));
  sync->getPolicy()->setMaxIntervalDuration(ros::Duration(0.1));
  sync->registerCallback(both);
  ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("closest_pose", 1);
  ros::spin();
}
"""

FILTER = """#include <ros/ros.h>
#include <std_msgs/Int32.h>
#include <functional>
#include <vector>

struct Lane { int lnid; };
struct Point { int pid; };
template <class T> using Filter = std::function<bool(const T&)>;
struct Map {
  std::vector<Lane> findByFilter(const Filter<Lane>& filter) const;
  std::vector<Point> findByFilter(const Filter<Point>& filter) const;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "decision");
  ros::NodeHandle nh;
  Map map;
  std::vector<Lane> lanes = map.findByFilter([](const Lane& lane) { return lane.lnid > 0; });
  ros::Publisher pub = nh.advertise<std_msgs::Int32>("lanes", 1);
  auto any = [](auto item) { return true; };
  std::vector<Point> points = map.findByFilter(Filter<Point>(any));
  ros::spin();
}
"""


def _extracted(tmp_path, text: str):
    (tmp_path / "package.xml").write_text(package_xml("aw"))
    source = tmp_path / "node.cpp"
    source.write_text(text)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="melodic")
    errors = [(d.location.line, d.message) for d in result.diagnostics
              if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")]
    return errors, sorted((c.kind, c.name) for c in result.calls)


def test_a_translation_times_a_rotation_is_a_transform(tmp_path) -> None:
    errors, calls = _extracted(tmp_path, NDT)
    assert errors == []
    assert calls == [("publish", "ndt_reliability"), ("read", "~x")]


def test_a_synchronizers_policy(tmp_path) -> None:
    errors, calls = _extracted(tmp_path, SYNC)
    assert errors == []
    assert ("publish", "closest_pose") in calls
    assert ("subscribe", "current_pose") in calls and ("subscribe", "current_velocity") in calls


def test_a_lambda_chooses_the_overload_of_its_argument_type(tmp_path) -> None:
    errors, calls = _extracted(tmp_path, FILTER)
    assert errors == []
    assert calls == [("publish", "lanes")]
