// haros_arch stand-in: Boost.Random (declarations only; every boost/random/... header
// stands in as this one), whose engines and distributions are those of <random>:
// cob_mimic's ``ros::Duration(real_dist_(gen_))`` reads a double from a
// ``boost::random::uniform_real_distribution<>`` (a permissive value there converts
// ambiguously, and the function calling the API was an error)
#ifndef HAROS_STANDIN_BOOST_RANDOM_HPP
#define HAROS_STANDIN_BOOST_RANDOM_HPP
#include <random>
namespace boost {
namespace random {
using std::mt19937;
using std::mt19937_64;
using std::minstd_rand;
using std::random_device;
using std::uniform_real_distribution;
using std::uniform_int_distribution;
using std::normal_distribution;
using std::bernoulli_distribution;
// an engine and a distribution as one generator
template <class Engine, class Distribution> class variate_generator {
public:
  typedef decltype(std::declval<Distribution&>()(std::declval<Engine&>())) result_type;
  variate_generator(Engine engine, Distribution distribution);
  result_type operator()();
  Engine& engine();
  Distribution& distribution();
};
}  // namespace random
using random::mt19937;
using random::mt19937_64;
using random::minstd_rand;
using random::random_device;
using random::normal_distribution;
using random::bernoulli_distribution;
using random::variate_generator;
// the older names, boost::uniform_int<> and boost::uniform_real<>
template <class T = int> class uniform_int : public std::uniform_int_distribution<T> {
public:
  uniform_int(T min = 0, T max = 9);
};
template <class T = double> class uniform_real : public std::uniform_real_distribution<T> {
public:
  uniform_real(T min = 0, T max = 1);
};
}  // namespace boost
#endif
