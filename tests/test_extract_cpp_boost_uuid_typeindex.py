"""Boost.Uuid, Boost.TypeIndex and boost::hash have stand-ins: fuse (dae85219) names
its variables and constraints by `boost::uuids::uuid`, their classes by
`boost::typeindex::stl_type_index::type_id<T>().pretty_name()`, and hashes them with
`boost::hash`; without them each use was a parse error near the node's calls (fuse's
trees: 214 clang errors -> 167, calls identical)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """
    #include <string>
    #include <unordered_map>
    #include <boost/functional/hash.hpp>
    #include <boost/type_index/stl_type_index.hpp>
    #include <boost/uuid/uuid.hpp>
    #include <boost/uuid/uuid_generators.hpp>
    #include <boost/uuid/uuid_io.hpp>
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    using UUID = boost::uuids::uuid;

    struct Variable {
      std::string type() const {
        return boost::typeindex::stl_type_index::type_id<Variable>().pretty_name();
      }
      UUID id = boost::uuids::random_generator()();
    };

    int main(int argc, char** argv) {
      ros::init(argc, argv, "ids");
      ros::NodeHandle nh;
      Variable v;
      std::unordered_map<UUID, int, boost::hash<UUID>> seen;
      std::size_t seed = 0;
      boost::hash_combine(seed, boost::uuids::hash_value(v.id));
      UUID named = boost::uuids::name_generator(boost::uuids::nil_uuid())("robot");
      if (named != v.id && !v.id.is_nil()) {
        ros::Publisher pub = nh.advertise<std_msgs::String>(boost::uuids::to_string(named), 1);
      }
      ros::Publisher types = nh.advertise<std_msgs::String>(v.type(), 1);
      ros::spin();
    }
    """


def _parsed(write_tree, name: str, source: str):
    """The result of one ROS 1 package's one source, ``src/<name>.cpp``."""
    root = write_tree({
        f"{name}/package.xml": package_xml(name, "catkin").replace(
            "</package>", "<depend>roscpp</depend><depend>std_msgs</depend></package>"),
        f"{name}/src/{name}.cpp": source})
    return extract_cpp([str(root / name / "src" / f"{name}.cpp")], scan([str(root)]),
                       cache_dir=None)


def _said(result, strict: bool = False) -> list[str]:
    """The parse errors a result says (``strict``: headers stood in for and names
    declared permissively too)."""
    codes = ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", *(
        ("CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED") if strict else ()))
    return [d.message for d in result.diagnostics if d.code in codes]


def test_boost_uuid_type_index_and_hash_parse(write_tree) -> None:
    result = _parsed(write_tree, "ids", NODE)
    assert not _said(result, strict=True)
    assert {c.kind for c in result.calls} == {"publish"}


REVERSE = """
    #include <map>
    #include <string>
    #include <vector>
    #include <iterator>
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "last");
      ros::NodeHandle nh;
      std::map<int, std::string> topics{{1, "a"}, {2, "b"}};
      auto last = topics.rbegin();
      std::vector<int> ids{1, 2};
      int newest = *std::make_reverse_iterator(ids.end());
      if (last != topics.rend() && newest > 0) {
        ros::Publisher pub = nh.advertise<std_msgs::String>(last->second, 1);
      }
      ros::spin();
    }
    """


def test_a_map_walked_backwards_parses(write_tree) -> None:
    """``m.rbegin()->first`` of a map (fuse's transaction queues, rtabmap's, mrpt's):
    the stand-in map had no reverse iterators, and ``std::reverse_iterator``'s ``*`` a
    deduced type without a body, so each use was a parse error."""
    result = _parsed(write_tree, "last", REVERSE)
    assert not _said(result)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "?")]


LOCKS = """
    #include <map>
    #include <mutex>
    #include <string>
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "queue");
      ros::NodeHandle nh;
      std::multimap<double, std::string> queue;
      auto first = queue.emplace(0.5, "scan");
      std::mutex mutex;
      std::unique_lock<std::mutex> lock(mutex, std::try_to_lock);
      if (lock && first->second == "scan") {
        ros::Publisher pub = nh.advertise<std_msgs::String>("queued", 1);
      }
      ros::spin();
    }
    """


def test_a_multimap_insertion_and_a_lock_test_parse(write_tree) -> None:
    """A multimap's ``emplace`` gives an iterator (fuse's transaction queues; the
    stand-in gave map's pair) and a ``unique_lock`` tests as a bool (``if (lock)``)."""
    result = _parsed(write_tree, "queue", LOCKS)
    assert not _said(result)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "queued")]


STRUCT = """
    #include <string>
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    void advertiseFrom(ros::NodeHandle& nh, const XmlRpc::XmlRpcValue& config) {
      std::string topic = static_cast<std::string>(config["topic"]);
      ros::Publisher pub = nh.advertise<std_msgs::String>("configured", 1);
    }

    int main(int argc, char** argv) {
      ros::init(argc, argv, "structs");
      ros::NodeHandle nh;
      XmlRpc::XmlRpcValue config;
      nh.getParam("config", config);
      advertiseFrom(nh, config);
      ros::spin();
    }
    """


def test_a_const_struct_parameter_is_read_by_key(write_tree) -> None:
    """``config["topic"]`` of a ``const XmlRpcValue&`` (noetic's xmlrpcpp has the const
    overloads; fuse's sensor configurations): the stand-in had none, an error near the
    node's calls that left fuse's nodes partial."""
    result = _parsed(write_tree, "structs", STRUCT)
    assert not _said(result)
    assert ("publish", "configured") in [(c.kind, c.name) for c in result.calls]


PURGE = """
    #include <map>
    #include <string>
    #include <ros/ros.h>
    #include <std_msgs/String.h>

    int main(int argc, char** argv) {
      ros::init(argc, argv, "purge");
      ros::NodeHandle nh;
      std::map<double, std::string> pending;
      auto until = pending.lower_bound(1.0);
      pending.erase(pending.begin(), until);
      ros::Publisher pub = nh.advertise<std_msgs::String>("purged", 1);
      ros::spin();
    }
    """


def test_a_map_range_erase_parses(write_tree) -> None:
    """``m.erase(first, last)`` of a map (fuse's batch optimizer purges its pending
    transactions so)."""
    result = _parsed(write_tree, "purge", PURGE)
    assert not _said(result)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "purged")]


def test_a_multiset_parses(write_tree) -> None:
    """``std::multiset`` (plansys2's PDDL parser prints one): a stand-in beside ``set``,
    whose insertions give the element's iterator (one parse error fewer on plansys2,
    calls identical)."""
    result = _parsed(write_tree, "counts", """
        #include <set>
        #include <ros/ros.h>
        #include <std_msgs/String.h>

        int main(int argc, char** argv) {
          ros::init(argc, argv, "counts");
          ros::NodeHandle nh;
          std::multiset<int> seen{1, 1, 2};
          std::multiset<int>::iterator at = seen.insert(2);
          auto range = seen.equal_range(1);
          if (at != seen.end() && range.first != range.second) {
            ros::Publisher pub = nh.advertise<std_msgs::String>("counts", 1);
          }
          ros::spin();
        }
        """)
    assert _said(result) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "counts")]


def test_boost_accumulators_parse(write_tree) -> None:
    """Boost.Accumulators (ROS 1 diff_drive_controller's rolling means of its velocities,
    novatel_gps_driver's offset statistics): a class whose member is an
    ``accumulator_set`` was invalid without it, and every call of its node's members an
    error near a call (novatel_gps_driver: 77 clang errors -> 48, 20 CPP_ERROR_NEAR_CALL
    -> 0; ros_controllers 22 parse errors fewer, calls identical)."""
    result = _parsed(write_tree, "odom", """
        #include <boost/accumulators/accumulators.hpp>
        #include <boost/accumulators/statistics/stats.hpp>
        #include <boost/accumulators/statistics/rolling_mean.hpp>
        #include <boost/accumulators/statistics/mean.hpp>
        #include <boost/accumulators/statistics/variance.hpp>
        #include <ros/ros.h>
        #include <std_msgs/Float64.h>

        namespace bacc = boost::accumulators;

        class Odometry {
        public:
          typedef bacc::accumulator_set<double, bacc::stats<bacc::tag::rolling_mean>> RollingMean;
          typedef bacc::tag::rolling_window RollingWindow;
          explicit Odometry(ros::NodeHandle& nh, size_t window)
            : linear_(RollingWindow::window_size = window) {
            pub_ = nh.advertise<std_msgs::Float64>("speed", 10);
          }
          void update(double v) {
            linear_(v);
            stats_(static_cast<float>(v));
            std_msgs::Float64 msg;
            msg.data = bacc::rolling_mean(linear_) + bacc::variance(stats_) + bacc::max(stats_);
            pub_.publish(msg);
          }
        private:
          RollingMean linear_;
          bacc::accumulator_set<float, bacc::stats<bacc::tag::max, bacc::tag::mean,
                                                   bacc::tag::variance>> stats_;
          ros::Publisher pub_;
        };

        int main(int argc, char** argv) {
          ros::init(argc, argv, "odom");
          ros::NodeHandle nh;
          Odometry odometry(nh, 10);
          odometry.update(1.0);
          ros::spin();
        }
        """)
    assert _said(result, strict=True) == []
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "speed")]
