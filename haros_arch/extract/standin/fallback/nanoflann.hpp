// haros_arch stand-in: nanoflann (declarations only), the header-only k-d tree library,
// for a workspace that has it installed (the nanoflann package, libnanoflann-dev), not as
// a copy of its own: a workspace's nanoflann.hpp wins. Its trees index points a dataset
// adaptor of the user gives (kdtree_get_point_count, kdtree_get_pt, kdtree_get_bbox) and
// answer nearest-neighbour and radius queries: no ROS call. The names of 1.3 to 1.5 side
// by side (SearchParams became SearchParameters, std::pair results ResultItem).
#ifndef HAROS_STANDIN_NANOFLANN_HPP
#define HAROS_STANDIN_NANOFLANN_HPP
#include <cstddef>
#include <cstdint>
#include <istream>
#include <ostream>
#include <utility>
#include <vector>

#ifndef NANOFLANN_VERSION
#define NANOFLANN_VERSION 0x154
#endif

namespace nanoflann {
struct SearchParameters {
  explicit SearchParameters(float eps = 0, bool sorted = true);
  float eps;
  bool sorted;
};
// 1.3's: its first argument was ignored
struct SearchParams {
  explicit SearchParams(int checks_ignored = 32, float eps = 0, bool sorted = true);
  int checks;
  float eps;
  bool sorted;
  operator SearchParameters() const;
};

template<typename IndexType = size_t, typename DistanceType = double>
struct ResultItem {
  ResultItem();
  ResultItem(IndexType index, DistanceType distance);
  IndexType first;
  DistanceType second;
};

template<typename DistanceType, typename IndexType = size_t, typename CountType = size_t>
class KNNResultSet {
 public:
  explicit KNNResultSet(CountType capacity);
  void init(IndexType* indices, DistanceType* dists);
  CountType size() const;
  bool empty() const;
  bool full() const;
  bool addPoint(DistanceType dist, IndexType index);
  DistanceType worstDist() const;
};

template<typename DistanceType, typename IndexType = size_t>
class RadiusResultSet {
 public:
  RadiusResultSet(DistanceType radius, std::vector<ResultItem<IndexType, DistanceType>>& indices);
  void init();
  void clear();
  size_t size() const;
  bool full() const;
  bool addPoint(DistanceType dist, IndexType index);
  DistanceType worstDist() const;
  ResultItem<IndexType, DistanceType> worst_item() const;
};

struct KDTreeSingleIndexAdaptorParams {
  KDTreeSingleIndexAdaptorParams(size_t leaf_max_size = 10, unsigned int flags = 0,
                                 unsigned int n_thread_build = 1);
  size_t leaf_max_size;
  unsigned int flags;
  unsigned int n_thread_build;
};

// the distances between a query and a point of the dataset
#define HAROS_NANOFLANN_DISTANCE(NAME) \
  template<class T, class DataSource, typename _DistanceType = T, \
           typename IndexType = uint32_t> \
  struct NAME { \
    typedef T ElementType; \
    typedef _DistanceType DistanceType; \
    explicit NAME(const DataSource& data_source); \
    DistanceType evalMetric(const T* a, const IndexType b_idx, size_t size) const; \
    template<typename U, typename V> DistanceType accum_dist(const U a, const V b, const size_t) const; \
  };
HAROS_NANOFLANN_DISTANCE(L1_Adaptor)
HAROS_NANOFLANN_DISTANCE(L2_Adaptor)
HAROS_NANOFLANN_DISTANCE(L2_Simple_Adaptor)
HAROS_NANOFLANN_DISTANCE(SO2_Adaptor)
HAROS_NANOFLANN_DISTANCE(SO3_Adaptor)
#undef HAROS_NANOFLANN_DISTANCE

struct Metric {};
#define HAROS_NANOFLANN_METRIC(NAME, ADAPTOR) \
  struct NAME : public Metric { \
    template<class T, class DataSource, typename IndexType = uint32_t> \
    struct traits { typedef ADAPTOR<T, DataSource, T, IndexType> distance_t; }; \
  };
HAROS_NANOFLANN_METRIC(metric_L1, L1_Adaptor)
HAROS_NANOFLANN_METRIC(metric_L2, L2_Adaptor)
HAROS_NANOFLANN_METRIC(metric_L2_Simple, L2_Simple_Adaptor)
HAROS_NANOFLANN_METRIC(metric_SO2, SO2_Adaptor)
HAROS_NANOFLANN_METRIC(metric_SO3, SO3_Adaptor)
#undef HAROS_NANOFLANN_METRIC

// a static tree over the dataset, built once (buildIndex)
template<typename Distance, class DatasetAdaptor, int32_t DIM = -1,
         typename IndexType = uint32_t>
class KDTreeSingleIndexAdaptor {
 public:
  typedef typename Distance::ElementType ElementType;
  typedef typename Distance::DistanceType DistanceType;
  KDTreeSingleIndexAdaptor(const int dimensionality, const DatasetAdaptor& inputData,
                           const KDTreeSingleIndexAdaptorParams& params = {});
  template<class... Args>
  KDTreeSingleIndexAdaptor(const int dimensionality, const DatasetAdaptor& inputData,
                           const KDTreeSingleIndexAdaptorParams& params, Args&&... args);
  void buildIndex();
  size_t size() const;
  size_t veclen() const;
  size_t usedMemory() const;
  template<typename ResultSet>
  bool findNeighbors(ResultSet& result, const ElementType* vec,
                     const SearchParameters& searchParams = SearchParameters()) const;
  template<typename OutIndex, typename OutDistance>
  size_t knnSearch(const ElementType* query_point, const size_t num_closest,
                   OutIndex* out_indices, OutDistance* out_distances, ...) const;
  template<typename Matches>
  size_t radiusSearch(const ElementType* query_point, const DistanceType& radius,
                      Matches& matches,
                      const SearchParameters& searchParams = SearchParameters()) const;
  template<class Callback>
  size_t radiusSearchCustomCallback(const ElementType* query_point, Callback& resultSet,
                                    const SearchParameters& searchParams = SearchParameters()) const;
  void saveIndex(std::ostream& stream) const;
  void loadIndex(std::istream& stream);
};

// a tree that points are added to and removed from
template<typename Distance, class DatasetAdaptor, int32_t DIM = -1,
         typename IndexType = uint32_t>
class KDTreeSingleIndexDynamicAdaptor {
 public:
  typedef typename Distance::ElementType ElementType;
  typedef typename Distance::DistanceType DistanceType;
  KDTreeSingleIndexDynamicAdaptor(const int dimensionality, const DatasetAdaptor& inputData,
                                  const KDTreeSingleIndexAdaptorParams& params = {},
                                  const size_t maximumPointCount = 1000000000U);
  void addPoints(IndexType start, IndexType end);
  void removePoint(size_t idx);
  template<typename ResultSet>
  bool findNeighbors(ResultSet& result, const ElementType* vec,
                     const SearchParameters& searchParams = SearchParameters()) const;
};

// a tree over the rows (or columns) of an Eigen matrix
template<class MatrixType, int32_t DIM = -1, class Distance = metric_L2,
         bool row_major = true>
struct KDTreeEigenMatrixAdaptor {
  typedef KDTreeEigenMatrixAdaptor<MatrixType, DIM, Distance, row_major> self_t;
  typedef typename MatrixType::Scalar num_t;
  typedef typename MatrixType::Index IndexType;
  typedef typename Distance::template traits<num_t, self_t, IndexType>::distance_t metric_t;
  typedef KDTreeSingleIndexAdaptor<metric_t, self_t, DIM, IndexType> index_t;
  index_t* index;
  template<class M>
  KDTreeEigenMatrixAdaptor(const size_t dimensionality, const M& mat,
                           const int leaf_max_size = 10);
  void query(const num_t* query_point, const size_t num_closest, IndexType* out_indices,
             num_t* out_distances_sq) const;
  size_t kdtree_get_point_count() const;
  num_t kdtree_get_pt(const IndexType idx, size_t dim) const;
  template<class BBOX> bool kdtree_get_bbox(BBOX& bb) const;
};
}  // namespace nanoflann
#endif
