// Stand-in for Boost.Accumulators, written for haros_arch: sample statistics kept as
// samples arrive (ROS 1 diff_drive_controller's rolling means of its velocities,
// novatel_gps_driver's offset statistics, ros_package_template's mean). Every
// boost/accumulators/... header stands in as this one. Declarations only.
#ifndef HAROS_BOOST_ACCUMULATORS_HPP
#define HAROS_BOOST_ACCUMULATORS_HPP
#include <cstddef>

namespace boost {
namespace accumulators {
// a named argument of a constructor (``tag::rolling_window::window_size = 10``)
struct haros_named_argument {};
struct haros_keyword {
  haros_named_argument operator=(std::size_t value) const;
};
namespace tag {
struct count {}; struct sum {}; struct mean {}; struct min {}; struct max {};
struct variance {}; struct lazy_variance {}; struct median {}; struct moment_2 {};
struct immediate_mean {}; struct rolling_mean {}; struct rolling_sum {};
struct rolling_count {}; struct error_of_mean {};
struct rolling_window { static const haros_keyword window_size; };
}  // namespace tag
template<class... Features> struct stats {};
template<class... Features> struct features {};
template<class Sample, class Features, class Weight = void> class accumulator_set {
public:
  typedef Sample sample_type;
  accumulator_set();
  template<class... Args> explicit accumulator_set(const Args&... args);
  // a sample arrives
  template<class... Args> void operator()(const Sample& sample, const Args&... args);
};
template<class A> std::size_t count(const A& acc);
template<class A> typename A::sample_type sum(const A& acc);
template<class A> typename A::sample_type mean(const A& acc);
template<class A> typename A::sample_type min(const A& acc);
template<class A> typename A::sample_type max(const A& acc);
template<class A> typename A::sample_type variance(const A& acc);
template<class A> typename A::sample_type lazy_variance(const A& acc);
template<class A> typename A::sample_type median(const A& acc);
template<class A> typename A::sample_type error_of_mean(const A& acc);
template<class A> typename A::sample_type rolling_mean(const A& acc);
template<class A> typename A::sample_type rolling_sum(const A& acc);
template<class A> std::size_t rolling_count(const A& acc);
}  // namespace accumulators
}  // namespace boost
#endif
