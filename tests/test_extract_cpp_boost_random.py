"""Boost.Random in the stand-ins: cob_mimic draws the delay of its next random mimic
with ``ros::Duration(real_dist_(gen_))``, ``real_dist_`` a
``boost::random::uniform_real_distribution<>`` and ``gen_`` a ``boost::random::mt19937``.
Without the library the parse declared them permissively, the duration was built from
a permissive value (an ambiguous conversion: a clang error in the function that
advertises the node's service and calls ``createTimer``) and the node was partial."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <boost/random/uniform_int_distribution.hpp>
#include <boost/random/variate_generator.hpp>
class Mimic {
 public:
  bool init() {
    srv_ = nh_.advertiseService("set_mimic", &Mimic::set, this);
    int_dist_ = boost::random::uniform_int_distribution<>(0, 4);
    int pick = int_dist_(gen_);
    boost::variate_generator<boost::mt19937&, boost::uniform_real<> > coin(
        plain_, boost::uniform_real<>(0.0, 1.0));
    timer_ = nh_.createTimer(ros::Duration(real_dist_(gen_) + coin() + pick),
                             &Mimic::tick, this, true);
    pub_ = nh_.advertise<std_srvs::Empty::Request>("chosen", 1);
    return true;
  }
  bool set(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  void tick(const ros::TimerEvent&);
 private:
  ros::NodeHandle nh_{"~"};
  ros::ServiceServer srv_;
  ros::Timer timer_;
  ros::Publisher pub_;
  boost::random::mt19937 gen_;
  boost::mt19937 plain_;
  boost::random::uniform_real_distribution<> real_dist_{60.0, 90.0};
  boost::random::uniform_int_distribution<> int_dist_;
};
int main(int argc, char** argv) {
  ros::init(argc, argv, "mimic");
  Mimic mimic;
  mimic.init();
  ros::spin();
}
"""


def test_boost_random_parses(tmp_path) -> None:
    (tmp_path / "mimic.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "mimic.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert sorted((c.kind, c.name) for c in result.calls if c.kind != "read") == [
        # the handle's default member initialiser makes them private
        ("publish", "~chosen"), ("server", "~set_mimic")]
    assert [d.code for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_INCLUDE_MISSING", "CPP_NAMES_DECLARED",
        "CPP_ERROR_NEAR_CALL")] == []
