"""A registration of the workspace's own (ndt_omp's NDT, fast_gicp's GICP, as LiDAR
odometry nodes vendor them) derives from ``pcl::Registration`` and takes its typedefs
(``PointCloudSource``, ``PointCloudTarget``), its protected state (``reg_name_``,
``target_``, ``final_transformation_``, ``update_visualizer_`` ...), overrides
``computeTransformation``, picks its ``Ptr`` by ``PCL_VERSION_CALC`` and prints with
``PCL_ERROR``. The PCL stand-in knew none of these (bench/README, survey Z46): the class
did not instantiate, ``Ndt<P, P>::Ptr ndt(new Ndt<P, P>())`` declared nothing, and every
``ndt->setX(pnh.param<...>(...))`` after it lost its parameter read (the node partial)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

HEADER = """#pragma once
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl/registration/registration.h>
#include <pcl/registration/bfgs.h>
#include <pcl/console/print.h>

namespace mine {
template <typename PointSource, typename PointTarget>
class Ndt : public pcl::Registration<PointSource, PointTarget, float> {
 public:
  using Scalar = float;
  using Matrix4 = typename pcl::Registration<PointSource, PointTarget, Scalar>::Matrix4;
  using PointCloudSource =
      typename pcl::Registration<PointSource, PointTarget, Scalar>::PointCloudSource;
  using PointCloudTarget =
      typename pcl::Registration<PointSource, PointTarget, Scalar>::PointCloudTarget;
  using PointCloudTargetConstPtr = typename PointCloudTarget::ConstPtr;
#if PCL_VERSION >= PCL_VERSION_CALC(1, 10, 0)
  using Ptr = pcl::shared_ptr<Ndt<PointSource, PointTarget>>;
#else
  using Ptr = boost::shared_ptr<Ndt<PointSource, PointTarget>>;
#endif
  Ndt() { reg_name_ = "Ndt"; }
  void setResolution(float r) {
    if (r <= 0) { PCL_ERROR("[%s] bad resolution\\n", reg_name_.c_str()); return; }
    resolution_ = r;
  }
  void setInputTarget(const PointCloudTargetConstPtr& cloud) override { target_ = cloud; }

 protected:
  using pcl::Registration<PointSource, PointTarget, Scalar>::reg_name_;
  using pcl::Registration<PointSource, PointTarget, Scalar>::target_;
  using pcl::Registration<PointSource, PointTarget, Scalar>::nr_iterations_;
  using pcl::Registration<PointSource, PointTarget, Scalar>::final_transformation_;
  using pcl::Registration<PointSource, PointTarget, Scalar>::converged_;
  using pcl::Registration<PointSource, PointTarget, Scalar>::update_visualizer_;
  void computeTransformation(PointCloudSource& output, const Matrix4& guess) override {
    nr_iterations_ = 0;
    final_transformation_ = guess;
    converged_ = true;
    if (update_visualizer_) {}
  }
  struct Functor : public BFGSDummyFunctor<double, 6> {
    double operator()(const Eigen::Matrix<double, 6, 1>& x) override { return 0; }
    void df(const Eigen::Matrix<double, 6, 1>& x, Eigen::Matrix<double, 6, 1>& df) override {}
    void fdf(const Eigen::Matrix<double, 6, 1>& x, double& f,
             Eigen::Matrix<double, 6, 1>& df) override {}
  };
  float resolution_;
};
}  // namespace mine
"""

NODE = """#include <ros/ros.h>
#include <std_msgs/String.h>
#include "ndt.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "odometry");
  ros::NodeHandle pnh("~");
  using PointT = pcl::PointXYZI;
  mine::Ndt<PointT, PointT>::Ptr ndt(new mine::Ndt<PointT, PointT>());
  ndt->setResolution(pnh.param<double>("ndt_resolution", 1.0));
  ndt->setMaximumIterations(pnh.param<int>("max_iterations", 64));
  ros::Publisher pub = pnh.advertise<std_msgs::String>("status", 1);
  ros::spin();
}
"""


def test_a_registration_of_the_workspace_s_own_keeps_its_node_s_calls(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("odometry"))
    (tmp_path / "ndt.hpp").write_text(HEADER)
    source = tmp_path / "node.cpp"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_CALL_MISSED")] == []
    assert [(c.kind, c.name, c.location.line) for c in result.calls] == [
        ("read", "~ndt_resolution", 10),
        ("read", "~max_iterations", 11),
        ("publish", "~status", 12),
    ]
