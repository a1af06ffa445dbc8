// haros_arch stand-in: the parts of the Point Cloud Library (PCL) ROS nodes use
// (declarations only). Read only when the workspace has no PCL header by that name: every
// <pcl/...> header stands in as this file. Pointers are std::shared_ptr in a ROS 2 unit
// (PCL >= 1.11) and boost::shared_ptr in a ROS 1 unit (HAROS_UNIT_ROS 1: Noetic's PCL 1.10,
// Melodic's 1.8), so a ROS 1 node's ``Filter<T>::Ptr f = boost::shared_ptr<VoxelGrid<T>>``
// is an assignment as on the robot (a ROS 1 callback deduces its message type from either).
#ifndef HAROS_STANDIN_PCL
#define HAROS_STANDIN_PCL
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>
#include <Eigen/Dense>

// -- pcl_macros.h / register_point_struct.h / instantiate.hpp -------------------------------
#ifndef PCL_NO_PRECOMPILE
#define PCL_NO_PRECOMPILE
#endif
#define PCL_MAKE_ALIGNED_OPERATOR_NEW
#define PCL_EXPORTS
#define PCL_DEPRECATED(...)
#define PCL_ALIGN(alignment) alignas(alignment)
#define PCL_ADD_UNION_POINT4D \
  union EIGEN_ALIGN16 { float data[4]; struct { float x; float y; float z; }; };
#define PCL_ADD_EIGEN_MAPS_POINT4D \
  Eigen::Vector3f getVector3fMap() const; Eigen::Vector4f getVector4fMap() const; \
  Eigen::Vector4f getArray4fMap() const; Eigen::Vector3f getArray3fMap() const;
#define PCL_ADD_POINT4D PCL_ADD_UNION_POINT4D PCL_ADD_EIGEN_MAPS_POINT4D
#define PCL_ADD_UNION_NORMAL4D \
  union EIGEN_ALIGN16 { float data_n[4]; float normal[3]; \
    struct { float normal_x; float normal_y; float normal_z; }; };
#define PCL_ADD_EIGEN_MAPS_NORMAL4D \
  Eigen::Vector3f getNormalVector3fMap() const; Eigen::Vector4f getNormalVector4fMap() const;
#define PCL_ADD_NORMAL4D PCL_ADD_UNION_NORMAL4D PCL_ADD_EIGEN_MAPS_NORMAL4D
#define PCL_ADD_UNION_RGB \
  union { union { struct { std::uint8_t b; std::uint8_t g; std::uint8_t r; std::uint8_t a; }; \
    float rgb; }; std::uint32_t rgba; };
#define PCL_ADD_EIGEN_MAPS_RGB \
  Eigen::Vector3i getRGBVector3i() const; Eigen::Vector4i getRGBVector4i() const; \
  Eigen::Vector4i getRGBAVector4i() const;
#define PCL_ADD_RGB PCL_ADD_UNION_RGB PCL_ADD_EIGEN_MAPS_RGB
#define PCL_ADD_INTENSITY struct { float intensity; };
#define PCL_ADD_INTENSITY_8U struct { std::uint8_t intensity; };
#define PCL_ADD_INTENSITY_32U struct { std::uint32_t intensity; };
// (type, name, tag) sequences of the fields: a registration declares nothing a node calls
#define POINT_CLOUD_REGISTER_POINT_STRUCT(name, fseq)
#define POINT_CLOUD_REGISTER_POINT_WRAPPER(wrapper, pod)
#define PCL_INSTANTIATE(TEMPLATE, POINT_TYPES)
#define PCL_INSTANTIATE_PRODUCT(TEMPLATE, PRODUCT)
// console/print.h: printf-like messages
#define PCL_ALWAYS(...) ((void)0)
#define PCL_ERROR(...) ((void)0)
#define PCL_WARN(...) ((void)0)
#define PCL_INFO(...) ((void)0)
#define PCL_DEBUG(...) ((void)0)
#define PCL_VERBOSE(...) ((void)0)
// pcl_config.h: the version this stand-in's API is (std::shared_ptr pointers, PCL 1.12, the
// version of Humble's Ubuntu; in a ROS 1 unit boost::shared_ptr pointers, PCL 1.10, the
// version of Noetic's Ubuntu), so a node's ``#if PCL_VERSION >= PCL_VERSION_CALC(1, 10, 0)``
// takes the branch that names ``pcl::shared_ptr``
#if defined(HAROS_UNIT_ROS) && HAROS_UNIT_ROS == 1
#define HAROS_PCL_BOOST_POINTERS 1
#endif
#define PCL_MAJOR_VERSION 1
#ifdef HAROS_PCL_BOOST_POINTERS
#define PCL_MINOR_VERSION 10
#define PCL_REVISION_VERSION 0
#define PCL_VERSION_PRETTY "1.10.0"
#else
#define PCL_MINOR_VERSION 12
#define PCL_REVISION_VERSION 1
#define PCL_VERSION_PRETTY "1.12.1"
#endif
#define PCL_DEV_VERSION 0
#define PCL_VERSION_CALC(MAJ, MIN, PATCH) ((MAJ) * 100000 + (MIN) * 100 + (PATCH))
#define PCL_VERSION \
  PCL_VERSION_CALC(PCL_MAJOR_VERSION, PCL_MINOR_VERSION, PCL_REVISION_VERSION)
#define PCL_VERSION_COMPARE(OP, MAJ, MIN, PATCH) \
  (PCL_VERSION * 10 + PCL_DEV_VERSION OP PCL_VERSION_CALC(MAJ, MIN, PATCH) * 10)
#define PCL_XYZ_POINT_TYPES (pcl::PointXYZ)(pcl::PointXYZI)(pcl::PointXYZRGB)(pcl::PointXYZRGBA)
#define PCL_POINT_TYPES PCL_XYZ_POINT_TYPES

#ifdef HAROS_PCL_BOOST_POINTERS
#include <boost/shared_ptr.hpp>
#include <boost/make_shared.hpp>
#endif

namespace pcl {
#ifdef HAROS_PCL_BOOST_POINTERS
template<class T> using shared_ptr = boost::shared_ptr<T>;  // PCL 1.10's pcl/memory.h
#else
template<class T> using shared_ptr = std::shared_ptr<T>;
#endif
template<class T, class... Args> shared_ptr<T> make_shared(Args&&... args);
typedef int index_t;
typedef std::uint32_t uindex_t;
typedef std::vector<index_t> Indices;
typedef shared_ptr<Indices> IndicesPtr;
typedef shared_ptr<const Indices> IndicesConstPtr;
template<class T> using AlignedVector = std::vector<T, Eigen::aligned_allocator<T>>;

// -- PCLHeader.h, PointIndices.h, ModelCoefficients.h, Vertices.h, PCLPointCloud2.h ------------
struct PCLHeader {
  std::uint32_t seq;
  std::uint64_t stamp;
  std::string frame_id;
  typedef shared_ptr<PCLHeader> Ptr;
  typedef shared_ptr<const PCLHeader> ConstPtr;
};
struct PointIndices {
  PCLHeader header;
  Indices indices;
  typedef shared_ptr<PointIndices> Ptr;
  typedef shared_ptr<const PointIndices> ConstPtr;
};
typedef PointIndices::Ptr PointIndicesPtr;
typedef PointIndices::ConstPtr PointIndicesConstPtr;
struct ModelCoefficients {
  PCLHeader header;
  std::vector<float> values;
  typedef shared_ptr<ModelCoefficients> Ptr;
  typedef shared_ptr<const ModelCoefficients> ConstPtr;
};
struct Vertices {
  Indices vertices;
  typedef shared_ptr<Vertices> Ptr;
  typedef shared_ptr<const Vertices> ConstPtr;
};
struct PCLPointField {
  std::string name;
  std::uint32_t offset;
  std::uint8_t datatype;
  std::uint32_t count;
  enum PointFieldTypes { INT8 = 1, UINT8 = 2, INT16 = 3, UINT16 = 4, INT32 = 5, UINT32 = 6,
                         FLOAT32 = 7, FLOAT64 = 8 };
};
struct PCLPointCloud2 {
  PCLHeader header;
  std::uint32_t height;
  std::uint32_t width;
  std::vector<PCLPointField> fields;
  std::uint8_t is_bigendian;
  std::uint32_t point_step;
  std::uint32_t row_step;
  std::vector<std::uint8_t> data;
  std::uint8_t is_dense;
  typedef shared_ptr<PCLPointCloud2> Ptr;
  typedef shared_ptr<const PCLPointCloud2> ConstPtr;
  PCLPointCloud2& operator+=(const PCLPointCloud2& rhs);
};
typedef PCLPointCloud2::Ptr PCLPointCloud2Ptr;
typedef PCLPointCloud2::ConstPtr PCLPointCloud2ConstPtr;

// -- point_types.h --------------------------------------------------------------------------
struct PointXYZ {
  PCL_ADD_POINT4D
  PointXYZ();
  PointXYZ(float x, float y, float z);
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
struct PointXYZI {
  PCL_ADD_POINT4D
  PCL_ADD_INTENSITY
  PointXYZI();
  explicit PointXYZI(float intensity);
  PointXYZI(float x, float y, float z, float intensity = 0.f);
};
struct PointXYZL {
  PCL_ADD_POINT4D
  std::uint32_t label;
  PointXYZL();
};
struct PointXYZRGB {
  PCL_ADD_POINT4D
  PCL_ADD_RGB
  PointXYZRGB();
  PointXYZRGB(std::uint8_t r, std::uint8_t g, std::uint8_t b);
  PointXYZRGB(float x, float y, float z);
  PointXYZRGB(float x, float y, float z, std::uint8_t r, std::uint8_t g, std::uint8_t b);
};
struct PointXYZRGBA {
  PCL_ADD_POINT4D
  PCL_ADD_RGB
  PointXYZRGBA();
  PointXYZRGBA(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a);
};
struct PointXYZRGBL {
  PCL_ADD_POINT4D
  PCL_ADD_RGB
  std::uint32_t label;
  PointXYZRGBL();
};
struct PointXY { float x; float y; PointXY(); PointXY(float x, float y); };
struct PointUV { float u; float v; };
struct InterestPoint { PCL_ADD_POINT4D float strength; };
struct Normal {
  PCL_ADD_NORMAL4D
  float curvature;
  Normal();
  Normal(float n_x, float n_y, float n_z);
};
struct Axis { PCL_ADD_NORMAL4D };
struct PointNormal {
  PCL_ADD_POINT4D
  PCL_ADD_NORMAL4D
  float curvature;
  PointNormal();
};
struct PointXYZRGBNormal {
  PCL_ADD_POINT4D
  PCL_ADD_NORMAL4D
  PCL_ADD_RGB
  float curvature;
  PointXYZRGBNormal();
};
struct PointXYZINormal {
  PCL_ADD_POINT4D
  PCL_ADD_NORMAL4D
  float intensity;
  float curvature;
  PointXYZINormal();
};
struct PointXYZLNormal {
  PCL_ADD_POINT4D
  PCL_ADD_NORMAL4D
  std::uint32_t label;
  float curvature;
};
struct PointWithRange { PCL_ADD_POINT4D float range; };
struct PointWithViewpoint { PCL_ADD_POINT4D float vp_x; float vp_y; float vp_z; };
struct PointSurfel {
  PCL_ADD_POINT4D
  PCL_ADD_NORMAL4D
  PCL_ADD_RGB
  float radius;
  float confidence;
  float curvature;
};
struct Label { std::uint32_t label; };
struct Intensity { float intensity; };
struct RGB { PCL_ADD_RGB };
struct FPFHSignature33 { float histogram[33]; };
struct ReferenceFrame { float rf[9]; };
struct Boundary { std::uint8_t boundary_point; };
// the feature descriptors of pcl/point_types.h (a name in capitals such as SHOT352, not
// declared, would be taken for a constant: pcl_ros' SHOTEstimation advertises a
// PointCloud<SHOT352>)
struct PFHSignature125 { float histogram[125]; };
struct PFHRGBSignature250 { float histogram[250]; };
struct PPFSignature { float f1; float f2; float f3; float f4; float alpha_m; };
struct NormalBasedSignature12 { float values[12]; };
struct ShapeContext1980 { float descriptor[1980]; float rf[9]; };
struct UniqueShapeContext1960 { float descriptor[1960]; float rf[9]; };
struct SHOT352 { float descriptor[352]; float rf[9]; };
struct SHOT1344 { float descriptor[1344]; float rf[9]; };
struct VFHSignature308 { float histogram[308]; };
struct GRSDSignature21 { float histogram[21]; };
struct GFPFHSignature16 { float histogram[16]; };
struct ESFSignature640 { float histogram[640]; };
struct BRISKSignature512 { float scale; float orientation; unsigned char descriptor[64]; };
struct Narf36 { float x; float y; float z; float roll; float pitch; float yaw; float descriptor[36]; };
struct MomentInvariants { float j1; float j2; float j3; };
struct PrincipalRadiiRSD { float r_min; float r_max; };
struct PrincipalCurvatures {
  float principal_curvature_x; float principal_curvature_y; float principal_curvature_z;
  float pc1; float pc2;
};
struct IntensityGradient { float gradient_x; float gradient_y; float gradient_z; };
template <int N> struct Histogram { float histogram[N]; };

namespace traits {
template<class PointT> struct has_field { static const bool value = true; };
template<class PointT> struct fieldList { typedef void type; };
}  // namespace traits

// -- point_cloud.h --------------------------------------------------------------------------
template<class PointT> class PointCloud {
 public:
  typedef PointT PointType;
  typedef std::vector<PointT, Eigen::aligned_allocator<PointT>> VectorType;
  typedef shared_ptr<PointCloud<PointT>> Ptr;
  typedef shared_ptr<const PointCloud<PointT>> ConstPtr;
  typedef typename VectorType::iterator iterator;
  typedef typename VectorType::const_iterator const_iterator;
  typedef typename VectorType::size_type size_type;
  PointCloud();
  PointCloud(std::uint32_t width, std::uint32_t height, const PointT& value = PointT());
  PointCloud(const PointCloud<PointT>& pc, const Indices& indices);
  PCLHeader header;
  VectorType points;
  std::uint32_t width;
  std::uint32_t height;
  bool is_dense;
  Eigen::Vector4f sensor_origin_;
  Eigen::Quaternionf sensor_orientation_;
  PointCloud& operator+=(const PointCloud& rhs);
  PointCloud operator+(const PointCloud& rhs);
  const PointT& at(int column, int row) const;
  PointT& at(int column, int row);
  const PointT& at(std::size_t n) const;
  PointT& at(std::size_t n);
  const PointT& operator()(std::size_t column, std::size_t row) const;
  PointT& operator()(std::size_t column, std::size_t row);
  const PointT& operator[](std::size_t n) const;
  PointT& operator[](std::size_t n);
  bool isOrganized() const;
  iterator begin();
  iterator end();
  const_iterator begin() const;
  const_iterator end() const;
  const_iterator cbegin() const;
  const_iterator cend() const;
  std::size_t size() const;
  index_t max_size() const;
  void reserve(std::size_t n);
  bool empty() const;
  PointT* data();
  const PointT* data() const;
  void resize(std::size_t count);
  void resize(std::size_t count, const PointT& value);
  void resize(index_t new_width, index_t new_height);
  void assign(std::size_t count, const PointT& value);
  template<class It> void assign(It first, It last);
  const PointT& front() const;
  PointT& front();
  const PointT& back() const;
  PointT& back();
  void push_back(const PointT& pt);
  void transient_push_back(const PointT& pt);
  template<class... Args> PointT& emplace_back(Args&&... args);
  iterator insert(iterator position, const PointT& pt);
  template<class It> void insert(iterator position, It first, It last);
  iterator erase(iterator position);
  iterator erase(iterator first, iterator last);
  void swap(PointCloud<PointT>& rhs);
  void clear();
  Ptr makeShared() const;
};

// the cloud a filter / search of ``PointT`` works on (PCLPointCloud2 is its own cloud)
template<class PointT> struct haros_cloud { typedef PointCloud<PointT> type; };
template<> struct haros_cloud<PCLPointCloud2> { typedef PCLPointCloud2 type; };

// -- pcl_base.h -----------------------------------------------------------------------------
template<class PointT> class PCLBase {
 public:
  typedef typename haros_cloud<PointT>::type PointCloud;
  typedef shared_ptr<PointCloud> PointCloudPtr;
  typedef shared_ptr<const PointCloud> PointCloudConstPtr;
  typedef shared_ptr<PointIndices> PointIndicesPtr;
  typedef shared_ptr<const PointIndices> PointIndicesConstPtr;
  PCLBase();
  virtual ~PCLBase();
  virtual void setInputCloud(const PointCloudConstPtr& cloud);
  const PointCloudConstPtr getInputCloud() const;
  // IndicesPtr, IndicesConstPtr or PointIndicesConstPtr (one template: the stand-in
  // shared_ptr converts from any other)
  template<class IndicesPointer> void setIndices(const IndicesPointer& indices);
  virtual void setIndices(std::size_t row_start, std::size_t col_start, std::size_t nb_rows,
                          std::size_t nb_cols);
  IndicesPtr getIndices();
  const PointT& operator[](std::size_t pos) const;
 protected:  // what a filter of the node's own (a subclass) reads
  PointCloudConstPtr input_;
  IndicesPtr indices_;
  bool use_indices_;
  bool fake_indices_;
  bool initCompute();
  bool deinitCompute();
};

// -- filters --------------------------------------------------------------------------------
template<class PointT> class Filter : public PCLBase<PointT> {
 public:
  typedef shared_ptr<Filter<PointT>> Ptr;
  typedef shared_ptr<const Filter<PointT>> ConstPtr;
  typedef typename PCLBase<PointT>::PointCloud PointCloud;
  explicit Filter(bool extract_removed_indices = false);
  IndicesConstPtr const getRemovedIndices() const;
  void getRemovedIndices(PointIndices& pi);
  void filter(PointCloud& output);
 protected:
  IndicesPtr removed_indices_;
  std::string filter_name_;
  bool extract_removed_indices_;
  const std::string& getClassName() const;
  virtual void applyFilter(PointCloud& output);
};
template<class PointT> class FilterIndices : public Filter<PointT> {
 public:
  typedef shared_ptr<FilterIndices<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const FilterIndices<PointT>> ConstPtr;
  typedef typename Filter<PointT>::PointCloud PointCloud;
  explicit FilterIndices(bool extract_removed_indices = false);
  using Filter<PointT>::filter;
  void filter(Indices& indices);
  void setNegative(bool negative);
  bool getNegative() const;
  void setKeepOrganized(bool keep_organized);
  bool getKeepOrganized() const;
  void setUserFilterValue(float value);
};
template<class PointT> class VoxelGrid : public Filter<PointT> {
 public:
  typedef shared_ptr<VoxelGrid<PointT>> Ptr;
  typedef shared_ptr<const VoxelGrid<PointT>> ConstPtr;
  VoxelGrid();
  void setLeafSize(const Eigen::Vector4f& leaf_size);
  void setLeafSize(float lx, float ly, float lz);
  Eigen::Vector3f getLeafSize() const;
  void setDownsampleAllData(bool downsample);
  bool getDownsampleAllData() const;
  void setMinimumPointsNumberPerVoxel(unsigned int min_points_per_voxel);
  unsigned int getMinimumPointsNumberPerVoxel() const;
  void setSaveLeafLayout(bool save_leaf_layout);
  bool getSaveLeafLayout() const;
  Eigen::Vector3i getMinBoxCoordinates() const;
  Eigen::Vector3i getMaxBoxCoordinates() const;
  Eigen::Vector3i getNrDivisions() const;
  Eigen::Vector3i getDivisionMultiplier() const;
  int getCentroidIndex(const PointT& p) const;
  Eigen::Vector3i getGridCoordinates(float x, float y, float z) const;
  int getCentroidIndexAt(const Eigen::Vector3i& ijk) const;
  void setFilterFieldName(const std::string& field_name);
  const std::string getFilterFieldName() const;
  void setFilterLimits(const double& limit_min, const double& limit_max);
  void getFilterLimits(double& limit_min, double& limit_max) const;
  void setFilterLimitsNegative(const bool limit_negative);
  std::vector<int> getLeafLayout() const;
 protected:
  Eigen::Vector4f leaf_size_;
  Eigen::Vector4f inverse_leaf_size_;
  bool downsample_all_data_;
  bool save_leaf_layout_;
  std::vector<int> leaf_layout_;
  Eigen::Vector4i min_b_, max_b_, div_b_, divb_mul_;
  std::string filter_field_name_;
  double filter_limit_min_;
  double filter_limit_max_;
  bool filter_limit_negative_;
  unsigned int min_points_per_voxel_;
};
template<class PointT> class ApproximateVoxelGrid : public Filter<PointT> {
 public:
  typedef shared_ptr<ApproximateVoxelGrid<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const ApproximateVoxelGrid<PointT>> ConstPtr;
  ApproximateVoxelGrid();
  void setLeafSize(const Eigen::Vector3f& leaf_size);
  void setLeafSize(float lx, float ly, float lz);
  void setDownsampleAllData(bool downsample);
};
template<class PointT> class PassThrough : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<PassThrough<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const PassThrough<PointT>> ConstPtr;
  explicit PassThrough(bool extract_removed_indices = false);
  void setFilterFieldName(const std::string& field_name);
  const std::string& getFilterFieldName() const;
  void setFilterLimits(const float& limit_min, const float& limit_max);
  void getFilterLimits(float& limit_min, float& limit_max) const;
  void setFilterLimitsNegative(const bool limit_negative);
  bool getFilterLimitsNegative() const;
};
template<class PointT> class CropBox : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<CropBox<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const CropBox<PointT>> ConstPtr;
  explicit CropBox(bool extract_removed_indices = false);
  void setMin(const Eigen::Vector4f& min_pt);
  Eigen::Vector4f getMin() const;
  void setMax(const Eigen::Vector4f& max_pt);
  Eigen::Vector4f getMax() const;
  void setTranslation(const Eigen::Vector3f& translation);
  Eigen::Vector3f getTranslation() const;
  void setRotation(const Eigen::Vector3f& rotation);
  Eigen::Vector3f getRotation() const;
  void setTransform(const Eigen::Affine3f& transform);
};
template<class PointT> class CropHull : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<CropHull<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const CropHull<PointT>> ConstPtr;
  CropHull();
  void setHullIndices(const std::vector<Vertices>& polygons);
  void setHullCloud(typename PCLBase<PointT>::PointCloudPtr points);
  void setDim(int dim);
  void setCropOutside(bool crop_outside);
};
template<class PointT> class ExtractIndices : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<ExtractIndices<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const ExtractIndices<PointT>> ConstPtr;
  explicit ExtractIndices(bool extract_removed_indices = false);
  void filterDirectly(typename PCLBase<PointT>::PointCloudPtr& cloud);
};
template<class PointT> class RadiusOutlierRemoval : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<RadiusOutlierRemoval<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const RadiusOutlierRemoval<PointT>> ConstPtr;
  explicit RadiusOutlierRemoval(bool extract_removed_indices = false);
  void setRadiusSearch(double radius);
  double getRadiusSearch();
  void setMinNeighborsInRadius(int min_pts);
  int getMinNeighborsInRadius();
};
template<class PointT> class StatisticalOutlierRemoval : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<StatisticalOutlierRemoval<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const StatisticalOutlierRemoval<PointT>> ConstPtr;
  explicit StatisticalOutlierRemoval(bool extract_removed_indices = false);
  void setMeanK(int nr_k);
  int getMeanK();
  void setStddevMulThresh(double stddev_mult);
  double getStddevMulThresh();
};
template<class PointT> class RandomSample : public FilterIndices<PointT> {
 public:
  typedef shared_ptr<RandomSample<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const RandomSample<PointT>> ConstPtr;
  explicit RandomSample(bool extract_removed_indices = false);
  void setSample(unsigned int sample);
  unsigned int getSample();
  void setSeed(unsigned int seed);
};
template<class PointT> void removeNaNFromPointCloud(const PointCloud<PointT>& cloud_in,
                                                     PointCloud<PointT>& cloud_out,
                                                     Indices& index);
template<class PointT> void removeNaNFromPointCloud(const PointCloud<PointT>& cloud_in,
                                                     Indices& index);

// -- kdtree / search ------------------------------------------------------------------------
template<class PointT> class KdTree {
 public:
  typedef shared_ptr<KdTree<PointT>> Ptr;
  typedef shared_ptr<const KdTree<PointT>> ConstPtr;
  typedef shared_ptr<const PointCloud<PointT>> PointCloudConstPtr;
  explicit KdTree(bool sorted = true);
  virtual ~KdTree();
  virtual void setInputCloud(const PointCloudConstPtr& cloud,
                             const IndicesConstPtr& indices = IndicesConstPtr());
  PointCloudConstPtr getInputCloud() const;
  virtual int nearestKSearch(const PointT& p_q, unsigned int k, Indices& k_indices,
                             std::vector<float>& k_sqr_distances) const;
  virtual int nearestKSearch(const PointCloud<PointT>& cloud, int index, unsigned int k,
                             Indices& k_indices, std::vector<float>& k_sqr_distances) const;
  virtual int nearestKSearch(int index, unsigned int k, Indices& k_indices,
                             std::vector<float>& k_sqr_distances) const;
  virtual int radiusSearch(const PointT& p_q, double radius, Indices& k_indices,
                           std::vector<float>& k_sqr_distances,
                           unsigned int max_nn = 0) const;
  virtual int radiusSearch(const PointCloud<PointT>& cloud, int index, double radius,
                           Indices& k_indices, std::vector<float>& k_sqr_distances,
                           unsigned int max_nn = 0) const;
  virtual int radiusSearch(int index, double radius, Indices& k_indices,
                           std::vector<float>& k_sqr_distances,
                           unsigned int max_nn = 0) const;
  virtual void setEpsilon(float eps);
  void setSortedResults(bool sorted);
};
template<class PointT, class Dist = void> class KdTreeFLANN : public KdTree<PointT> {
 public:
  typedef shared_ptr<KdTreeFLANN<PointT, Dist>> Ptr;
  typedef shared_ptr<const KdTreeFLANN<PointT, Dist>> ConstPtr;
  explicit KdTreeFLANN(bool sorted = true);
};
namespace search {
template<class PointT> class Search : public pcl::KdTree<PointT> {
 public:
  typedef shared_ptr<Search<PointT>> Ptr;
  typedef shared_ptr<const Search<PointT>> ConstPtr;
  explicit Search(const std::string& name = "", bool sorted = false);
  virtual const std::string& getName() const;
};
template<class PointT, class Tree = void> class KdTree : public Search<PointT> {
 public:
  typedef shared_ptr<KdTree<PointT, Tree>> Ptr;
  typedef shared_ptr<const KdTree<PointT, Tree>> ConstPtr;
  explicit KdTree(bool sorted = true);
};
template<class PointT> class Octree : public Search<PointT> {
 public:
  typedef shared_ptr<Octree<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const Octree<PointT>> ConstPtr;
  explicit Octree(double resolution);
};
template<class PointT> class OrganizedNeighbor : public Search<PointT> {
 public:
  typedef shared_ptr<OrganizedNeighbor<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const OrganizedNeighbor<PointT>> ConstPtr;
  explicit OrganizedNeighbor(bool sorted_results = false, float eps = 1e-4f,
                             unsigned pyramid_window_size = 5);
};
}  // namespace search

// -- segmentation / sample_consensus / features / surface -----------------------------------
enum SacModel { SACMODEL_PLANE, SACMODEL_LINE, SACMODEL_CIRCLE2D, SACMODEL_CIRCLE3D,
                SACMODEL_SPHERE, SACMODEL_CYLINDER, SACMODEL_CONE, SACMODEL_TORUS,
                SACMODEL_PARALLEL_LINE, SACMODEL_PERPENDICULAR_PLANE, SACMODEL_PARALLEL_LINES,
                SACMODEL_NORMAL_PLANE, SACMODEL_NORMAL_SPHERE, SACMODEL_REGISTRATION,
                SACMODEL_REGISTRATION_2D, SACMODEL_PARALLEL_PLANE,
                SACMODEL_NORMAL_PARALLEL_PLANE, SACMODEL_STICK };
const static int SAC_RANSAC = 0;
const static int SAC_LMEDS = 1;
const static int SAC_MSAC = 2;
const static int SAC_RRANSAC = 3;
const static int SAC_RMSAC = 4;
const static int SAC_MLESAC = 5;
const static int SAC_PROSAC = 6;
template<class PointT> class SACSegmentation : public PCLBase<PointT> {
 public:
  typedef typename KdTree<PointT>::Ptr SearchPtr;
  explicit SACSegmentation(bool random = false);
  void setModelType(int model);
  int getModelType() const;
  void setMethodType(int method);
  int getMethodType() const;
  void setDistanceThreshold(double threshold);
  double getDistanceThreshold() const;
  void setMaxIterations(int max_iterations);
  void setProbability(double probability);
  void setOptimizeCoefficients(bool optimize);
  void setRadiusLimits(const double& min_radius, const double& max_radius);
  void setAxis(const Eigen::Vector3f& ax);
  void setEpsAngle(double ea);
  void setSamplesMaxDist(const double& radius, SearchPtr search);
  virtual void segment(PointIndices& inliers, ModelCoefficients& model_coefficients);
};
template<class PointT, class PointNT> class SACSegmentationFromNormals
    : public SACSegmentation<PointT> {
 public:
  typedef shared_ptr<SACSegmentationFromNormals<PointT, PointNT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const SACSegmentationFromNormals<PointT, PointNT>> ConstPtr;
  explicit SACSegmentationFromNormals(bool random = false);
  void setInputNormals(const typename PointCloud<PointNT>::ConstPtr& normals);
  void setNormalDistanceWeight(double distance_weight);
};
template<class PointT> class EuclideanClusterExtraction : public PCLBase<PointT> {
 public:
  typedef typename KdTree<PointT>::Ptr KdTreePtr;
  EuclideanClusterExtraction();
  void setSearchMethod(const KdTreePtr& tree);
  KdTreePtr getSearchMethod() const;
  void setClusterTolerance(double tolerance);
  double getClusterTolerance() const;
  void setMinClusterSize(int min_cluster_size);
  int getMinClusterSize() const;
  void setMaxClusterSize(int max_cluster_size);
  int getMaxClusterSize() const;
  void extract(std::vector<PointIndices>& clusters);
};
template<class PointT> void extractEuclideanClusters(
    const PointCloud<PointT>& cloud, const typename KdTree<PointT>::Ptr& tree,
    float tolerance, std::vector<PointIndices>& clusters, unsigned int min_pts_per_cluster = 1,
    unsigned int max_pts_per_cluster = 0xffffffff);
template<class PointT> class SegmentDifferences : public PCLBase<PointT> {
 public:
  typedef typename KdTree<PointT>::Ptr KdTreePtr;
  SegmentDifferences();
  void setTargetCloud(const typename PointCloud<PointT>::ConstPtr& cloud);
  void setSearchMethod(const KdTreePtr& tree);
  void setDistanceThreshold(double sqr_threshold);
  double getDistanceThreshold();
  void segment(PointCloud<PointT>& output);
};
template<class PointInT, class PointOutT> class Feature : public PCLBase<PointInT> {
 public:
  typedef typename KdTree<PointInT>::Ptr KdTreePtr;
  void setSearchSurface(const typename PointCloud<PointInT>::ConstPtr& cloud);
  void setSearchMethod(const KdTreePtr& tree);
  void setKSearch(int k);
  void setRadiusSearch(double radius);
  void compute(PointCloud<PointOutT>& output);
};
template<class PointInT, class PointOutT> class NormalEstimation
    : public Feature<PointInT, PointOutT> {
 public:
  typedef shared_ptr<NormalEstimation<PointInT, PointOutT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const NormalEstimation<PointInT, PointOutT>> ConstPtr;
  NormalEstimation();
  void setViewPoint(float vpx, float vpy, float vpz);
  void useSensorOriginAsViewPoint();
};
template<class PointInT, class PointOutT> class NormalEstimationOMP
    : public NormalEstimation<PointInT, PointOutT> {
 public:
  typedef shared_ptr<NormalEstimationOMP<PointInT, PointOutT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const NormalEstimationOMP<PointInT, PointOutT>> ConstPtr;
  explicit NormalEstimationOMP(unsigned int nr_threads = 0);
  void setNumberOfThreads(unsigned int nr_threads = 0);
};
template<class PointT> class ConvexHull : public PCLBase<PointT> {
 public:
  typedef shared_ptr<ConvexHull<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const ConvexHull<PointT>> ConstPtr;
  ConvexHull();
  void setDimension(int dimension);
  void setComputeAreaVolume(bool value);
  double getTotalArea() const;
  double getTotalVolume() const;
  void reconstruct(PointCloud<PointT>& points, std::vector<Vertices>& polygons);
  void reconstruct(PointCloud<PointT>& points);
};
template<class PointT> class ConcaveHull : public ConvexHull<PointT> {
 public:
  typedef shared_ptr<ConcaveHull<PointT>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const ConcaveHull<PointT>> ConstPtr;
  ConcaveHull();
  void setAlpha(double alpha);
};

// -- registration ---------------------------------------------------------------------------
template<class PointSource, class PointTarget, class Scalar = float> class Registration
    : public PCLBase<PointSource> {
 public:
  typedef Eigen::Matrix<Scalar, 4, 4> Matrix4;
  typedef shared_ptr<Registration<PointSource, PointTarget, Scalar>> Ptr;
  typedef shared_ptr<const Registration<PointSource, PointTarget, Scalar>> ConstPtr;
  // the names a registration of the node's own (a subclass: NDT or GICP variants) takes
  typedef PointCloud<PointSource> PointCloudSource;
  typedef typename PointCloudSource::Ptr PointCloudSourcePtr;
  typedef typename PointCloudSource::ConstPtr PointCloudSourceConstPtr;
  typedef PointCloud<PointTarget> PointCloudTarget;
  typedef typename PointCloudTarget::Ptr PointCloudTargetPtr;
  typedef typename PointCloudTarget::ConstPtr PointCloudTargetConstPtr;
  typedef search::KdTree<PointTarget> KdTree;
  typedef typename search::KdTree<PointTarget>::Ptr KdTreePtr;
  typedef search::KdTree<PointSource> KdTreeReciprocal;
  typedef typename search::KdTree<PointSource>::Ptr KdTreeReciprocalPtr;
  using PCLBase<PointSource>::initCompute;
  using PCLBase<PointSource>::deinitCompute;
  using PCLBase<PointSource>::input_;
  using PCLBase<PointSource>::indices_;
  Registration();
  void setSearchMethodTarget(const KdTreePtr& tree, bool force_no_recompute = false);
  KdTreePtr getSearchMethodTarget() const;
  void setSearchMethodSource(const KdTreeReciprocalPtr& tree, bool force_no_recompute = false);
  KdTreeReciprocalPtr getSearchMethodSource() const;
  PointCloudSourceConstPtr const getInputSource();
  PointCloudTargetConstPtr const getInputTarget();
  virtual void setInputSource(const PointCloudSourceConstPtr& cloud);
  virtual void setInputTarget(const PointCloudTargetConstPtr& cloud);
  void setMaximumIterations(int nr_iterations);
  int getMaximumIterations();
  void setMaxCorrespondenceDistance(double distance_threshold);
  void setTransformationEpsilon(double epsilon);
  void setEuclideanFitnessEpsilon(double epsilon);
  void setRANSACOutlierRejectionThreshold(double inlier_threshold);
  Matrix4 getFinalTransformation();
  Matrix4 getLastIncrementalTransformation();
  bool hasConverged() const;
  double getFitnessScore(double max_range = 1e300);
  void align(PointCloud<PointSource>& output);
  void align(PointCloud<PointSource>& output, const Matrix4& guess);
  void setTransformationRotationEpsilon(double epsilon);
  double getTransformationEpsilon();
  double getMaxCorrespondenceDistance();
  int getRANSACIterations();
  void setRANSACIterations(int ransac_iterations);
  const std::string& getClassName() const;
 protected:  // what a registration of the node's own reads and writes
  std::string reg_name_;
  KdTreePtr tree_;
  KdTreeReciprocalPtr tree_reciprocal_;
  int nr_iterations_;
  int max_iterations_;
  int ransac_iterations_;
  PointCloudTargetConstPtr target_;
  Matrix4 final_transformation_;
  Matrix4 transformation_;
  Matrix4 previous_transformation_;
  double transformation_epsilon_;
  double transformation_rotation_epsilon_;
  double euclidean_fitness_epsilon_;
  double corr_dist_threshold_;
  double inlier_threshold_;
  bool converged_;
  int min_number_correspondences_;
  bool target_cloud_updated_;
  bool source_cloud_updated_;
  bool force_no_recompute_;
  bool force_no_recompute_reciprocal_;
  std::function<void(const PointCloud<PointSource>&, const std::vector<int>&,
                     const PointCloud<PointTarget>&, const std::vector<int>&)>
      update_visualizer_;
  bool initComputeReciprocal();
  // pure in PCL; declared here so the stand-in's own registrations are not abstract
  virtual void computeTransformation(PointCloudSource& output, const Matrix4& guess);
};
template<class PointSource, class PointTarget, class Scalar = float> class IterativeClosestPoint
    : public Registration<PointSource, PointTarget, Scalar> {
 public:
  typedef shared_ptr<IterativeClosestPoint<PointSource, PointTarget, Scalar>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const IterativeClosestPoint<PointSource, PointTarget, Scalar>> ConstPtr;
  IterativeClosestPoint();
  void setUseReciprocalCorrespondences(bool use_reciprocal_correspondence);
};
template<class PointSource, class PointTarget> class GeneralizedIterativeClosestPoint
    : public IterativeClosestPoint<PointSource, PointTarget> {
 public:
  typedef shared_ptr<GeneralizedIterativeClosestPoint<PointSource, PointTarget>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const GeneralizedIterativeClosestPoint<PointSource, PointTarget>> ConstPtr;
  GeneralizedIterativeClosestPoint();
  void setCorrespondenceRandomness(int k);
  void setMaximumOptimizerIterations(int max);
};
template<class PointSource, class PointTarget> class NormalDistributionsTransform
    : public Registration<PointSource, PointTarget> {
 public:
  typedef shared_ptr<NormalDistributionsTransform<PointSource, PointTarget>> Ptr;  // each class its own, as PCL's
  typedef shared_ptr<const NormalDistributionsTransform<PointSource, PointTarget>> ConstPtr;
  NormalDistributionsTransform();
  void setResolution(float resolution);
  void setStepSize(double step_size);
  void setOulierRatio(double outlier_ratio);
  double getTransformationProbability() const;
  int getFinalNumIteration() const;
};

// -- common ---------------------------------------------------------------------------------
template<class PointT> void getMinMax3D(const PointCloud<PointT>& cloud, PointT& min_pt,
                                        PointT& max_pt);
template<class PointT> void getMinMax3D(const PointCloud<PointT>& cloud,
                                        Eigen::Vector4f& min_pt, Eigen::Vector4f& max_pt);
template<class PointT> void getMinMax3D(const PointCloud<PointT>& cloud, const Indices& indices,
                                        Eigen::Vector4f& min_pt, Eigen::Vector4f& max_pt);
template<class PointT, class Vector> unsigned int compute3DCentroid(
    const PointCloud<PointT>& cloud, Vector& centroid);
template<class PointT, class Vector> unsigned int compute3DCentroid(
    const PointCloud<PointT>& cloud, const Indices& indices, Vector& centroid);
template<class PointT, class Matrix, class Vector> unsigned int computeCovarianceMatrix(
    const PointCloud<PointT>& cloud, const Vector& centroid, Matrix& covariance_matrix);
template<class PointT, class Matrix, class Vector> unsigned int computeMeanAndCovarianceMatrix(
    const PointCloud<PointT>& cloud, Matrix& covariance_matrix, Vector& centroid);
template<class PointT> class CentroidPoint {
 public:
  void add(const PointT& point);
  template<class PointOutT> void get(PointOutT& point) const;
  std::size_t getSize() const;
};
template<class PointT, class Transform> void transformPointCloud(
    const PointCloud<PointT>& cloud_in, PointCloud<PointT>& cloud_out,
    const Transform& transform, bool copy_all_fields = true);
template<class PointT, class Transform> void transformPointCloud(
    const PointCloud<PointT>& cloud_in, const Indices& indices, PointCloud<PointT>& cloud_out,
    const Transform& transform, bool copy_all_fields = true);
template<class PointT, class Transform> void transformPointCloudWithNormals(
    const PointCloud<PointT>& cloud_in, PointCloud<PointT>& cloud_out,
    const Transform& transform, bool copy_all_fields = true);
template<class PointT, class Transform> PointT transformPoint(const PointT& point,
                                                                 const Transform& transform);
Eigen::Affine3f getTransformation(float x, float y, float z, float roll, float pitch,
                                  float yaw);
void getTranslationAndEulerAngles(const Eigen::Affine3f& t, float& x, float& y, float& z,
                                  float& roll, float& pitch, float& yaw);
template<class PointA, class PointB> float euclideanDistance(const PointA& p1, const PointB& p2);
template<class PointA, class PointB> float squaredEuclideanDistance(const PointA& p1,
                                                                    const PointB& p2);
template<class PointT> bool isFinite(const PointT& pt);
template<class PointT> bool isXYZFinite(const PointT& pt);
template<class PointInT, class PointOutT> void copyPointCloud(const PointCloud<PointInT>& in,
                                                               PointCloud<PointOutT>& out);
template<class PointInT, class PointOutT> void copyPointCloud(const PointCloud<PointInT>& in,
                                                               const Indices& indices,
                                                               PointCloud<PointOutT>& out);
template<class PointInT, class PointOutT> void copyPointCloud(const PointCloud<PointInT>& in,
                                                               const PointIndices& indices,
                                                               PointCloud<PointOutT>& out);
template<class PointInT, class PointOutT> void copyPointCloud(
    const PointCloud<PointInT>& in, const std::vector<PointIndices>& indices,
    PointCloud<PointOutT>& out);
void copyPointCloud(const PCLPointCloud2& in, PCLPointCloud2& out);
void copyPointCloud(const PCLPointCloud2& in, const Indices& indices, PCLPointCloud2& out);
template<class PointT> bool concatenate(const PointCloud<PointT>& a, const PointCloud<PointT>& b,
                                        PointCloud<PointT>& out);
bool concatenate(const PCLPointCloud2& a, const PCLPointCloud2& b, PCLPointCloud2& out);
bool concatenatePointCloud(const PCLPointCloud2& a, const PCLPointCloud2& b,
                           PCLPointCloud2& out);
template<class PointIn1T, class PointIn2T, class PointOutT> void concatenateFields(
    const PointCloud<PointIn1T>& a, const PointCloud<PointIn2T>& b, PointCloud<PointOutT>& out);
template<class PointT> void toPCLPointCloud2(const PointCloud<PointT>& cloud,
                                             PCLPointCloud2& msg);
template<class PointT> void fromPCLPointCloud2(const PCLPointCloud2& msg,
                                               PointCloud<PointT>& cloud);
template<class PointT> void createMapping(const std::vector<PCLPointField>& msg_fields,
                                          std::vector<int>& field_map);
template<class PointT> int getFieldIndex(const std::string& field_name);
int getFieldIndex(const PCLPointCloud2& cloud, const std::string& field_name);
template<class PointT> std::string getFieldsList(const PointCloud<PointT>& cloud);
std::string getFieldsList(const PCLPointCloud2& cloud);
int getFieldSize(const int datatype);
template<class T> T rad2deg(T alpha);
template<class T> T deg2rad(T alpha);
template<class V> double getAngle3D(const V& v1, const V& v2, bool in_degree = false);

// -- io -------------------------------------------------------------------------------------
class PCDReader {
 public:
  int read(const std::string& file_name, PCLPointCloud2& cloud, const int offset = 0);
  template<class PointT> int read(const std::string& file_name, PointCloud<PointT>& cloud,
                                  const int offset = 0);
};
class PCDWriter {
 public:
  int write(const std::string& file_name, const PCLPointCloud2& cloud, bool binary = false);
  // with the sensor's origin and orientation (pcl_ros' PCDWriter nodelet)
  int write(const std::string& file_name, const PCLPointCloud2& cloud,
            const Eigen::Vector4f& origin, const Eigen::Quaternionf& orientation,
            bool binary = false);
  template<class PointT> int write(const std::string& file_name, const PointCloud<PointT>& cloud,
                                   bool binary = false);
  template<class PointT> int writeBinary(const std::string& file_name,
                                         const PointCloud<PointT>& cloud);
  template<class PointT> int writeASCII(const std::string& file_name,
                                        const PointCloud<PointT>& cloud, const int precision = 8);
};
namespace io {
int loadPCDFile(const std::string& file_name, PCLPointCloud2& cloud);
template<class PointT> int loadPCDFile(const std::string& file_name, PointCloud<PointT>& cloud);
int savePCDFile(const std::string& file_name, const PCLPointCloud2& cloud, bool binary = false);
template<class PointT> int savePCDFile(const std::string& file_name,
                                       const PointCloud<PointT>& cloud, bool binary = false);
template<class PointT> int savePCDFile(const std::string& file_name,
                                       const PointCloud<PointT>& cloud,
                                       const Indices& indices, bool binary = false);
template<class PointT> int savePCDFileASCII(const std::string& file_name,
                                            const PointCloud<PointT>& cloud);
template<class PointT> int savePCDFileBinary(const std::string& file_name,
                                             const PointCloud<PointT>& cloud);
template<class PointT> int savePCDFileBinaryCompressed(const std::string& file_name,
                                                       const PointCloud<PointT>& cloud);
int loadPLYFile(const std::string& file_name, PCLPointCloud2& cloud);
template<class PointT> int loadPLYFile(const std::string& file_name, PointCloud<PointT>& cloud);
template<class PointT> int savePLYFile(const std::string& file_name,
                                       const PointCloud<PointT>& cloud, bool binary = false);
}  // namespace io
using io::loadPCDFile;
using io::savePCDFile;
using io::savePCDFileASCII;
using io::savePCDFileBinary;
using io::savePCDFileBinaryCompressed;

namespace console {
enum VERBOSITY_LEVEL { L_ALWAYS, L_ERROR, L_WARN, L_INFO, L_DEBUG, L_VERBOSE };
void setVerbosityLevel(VERBOSITY_LEVEL level);
}  // namespace console
}  // namespace pcl

// registration/bfgs.h (global namespace): the functor a registration's optimiser derives from
template<typename _Scalar, int NX = Eigen::Dynamic> struct BFGSDummyFunctor {
  typedef _Scalar Scalar;
  enum { InputsAtCompileTime = NX };
  typedef Eigen::Matrix<Scalar, InputsAtCompileTime, 1> VectorType;
  const int m_inputs;
  BFGSDummyFunctor();
  BFGSDummyFunctor(int inputs);
  virtual ~BFGSDummyFunctor();
  int inputs() const;
  virtual double operator()(const VectorType& x) = 0;
  virtual void df(const VectorType& x, VectorType& df) = 0;
  virtual void fdf(const VectorType& x, Scalar& f, VectorType& df) = 0;
};
#endif
