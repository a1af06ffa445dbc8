// haros_arch stand-in: the parts of ROS 1 navigation's costmap_2d that plugins and nodes
// outside the navigation stack use (declarations only; every costmap_2d/... header stands
// in as this one, read only when the workspace has no costmap_2d package,
// headers.FALLBACK_UMBRELLAS), as of noetic (tf2). A layer's members are its base's, so
// a layer's onInitialize parses: ``ros::NodeHandle nh("~/" + name_)``, where name_ is
// the plugin name move_base gives it at run time (unknown here: the plugin attachment
// fills it). Classes that make ROS calls of their own are declared HAROS_UNREAD: the
// costmap node (Costmap2DROS reads its parameters, loads its layers, publishes the grid
// and the footprint) and its grid publisher; a node that builds one is partial
// (CPP_CLASS_UNSEEN). The functions that read parameters from a handle they are given
// (makeFootprintFromParams, writeFootprintToParam) are not declared: the parse declares
// them permissively and a node that gives them its handle is partial
// (CPP_NODE_TO_UNKNOWN). The dynamic_reconfigure configs carry their .cfg parameters as
// the synthesised configs do (extract.cpp.reconfigure).
#ifndef HAROS_STANDIN_COSTMAP_2D_ROS1_H
#define HAROS_STANDIN_COSTMAP_2D_ROS1_H
#include <cmath>
#include <list>
#include <string>
#include <vector>
#include <boost/shared_ptr.hpp>
#include <boost/thread.hpp>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <message_filters/subscriber.h>
#include <laser_geometry/laser_geometry.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Point.h>
#include <geometry_msgs/Point32.h>
#include <geometry_msgs/Polygon.h>
#include <geometry_msgs/PolygonStamped.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#ifndef HAROS_UNREAD
#define HAROS_UNREAD __attribute__((annotate("haros_unread")))
#endif
#define HAROS_COSTMAP_CONFIG __attribute__((annotate("haros_arch.reconfigure_config")))
#define HAROS_COSTMAP_PARAM(text) __attribute__((annotate("haros_arch.reconfigure " text)))

// costmap_math.h: free functions of the global namespace
inline double sign(double x) { return x < 0.0 ? -1.0 : 1.0; }
inline double sign0(double x) { return x < 0.0 ? -1.0 : (x > 0.0 ? 1.0 : 0.0); }
inline double distance(double x0, double y0, double x1, double y1) {
  return std::hypot(x1 - x0, y1 - y0);
}
double distanceToLine(double pX, double pY, double x0, double y0, double x1, double y1);
bool intersects(std::vector<geometry_msgs::Point>& polygon, float testx, float testy);
bool intersects(std::vector<geometry_msgs::Point>& polygon1,
                std::vector<geometry_msgs::Point>& polygon2);

namespace costmap_2d {

// cost_values.h
static const unsigned char NO_INFORMATION = 255;
static const unsigned char LETHAL_OBSTACLE = 254;
static const unsigned char INSCRIBED_INFLATED_OBSTACLE = 253;
static const unsigned char FREE_SPACE = 0;

struct MapLocation { unsigned int x; unsigned int y; };

// the configs cfg/*.cfg generate (dynamic_reconfigure), each with its parameters
struct HAROS_COSTMAP_CONFIG
    HAROS_COSTMAP_PARAM("[\"enabled\", \"bool\", true]") GenericPluginConfig {
  bool enabled;
  static const GenericPluginConfig& __getDefault__();
};
struct HAROS_COSTMAP_CONFIG
    HAROS_COSTMAP_PARAM("[\"enabled\", \"bool\", true]")
    HAROS_COSTMAP_PARAM("[\"footprint_clearing_enabled\", \"bool\", true]")
    HAROS_COSTMAP_PARAM("[\"max_obstacle_height\", \"double\", 2.0]")
    HAROS_COSTMAP_PARAM("[\"combination_method\", \"int\", 1]") ObstaclePluginConfig {
  bool enabled;
  bool footprint_clearing_enabled;
  double max_obstacle_height;
  int combination_method;
  static const ObstaclePluginConfig& __getDefault__();
};
struct HAROS_COSTMAP_CONFIG
    HAROS_COSTMAP_PARAM("[\"enabled\", \"bool\", true]")
    HAROS_COSTMAP_PARAM("[\"footprint_clearing_enabled\", \"bool\", true]")
    HAROS_COSTMAP_PARAM("[\"max_obstacle_height\", \"double\", 2.0]")
    HAROS_COSTMAP_PARAM("[\"origin_z\", \"double\", 0.0]")
    HAROS_COSTMAP_PARAM("[\"z_resolution\", \"double\", 0.2]")
    HAROS_COSTMAP_PARAM("[\"z_voxels\", \"int\", 10]")
    HAROS_COSTMAP_PARAM("[\"unknown_threshold\", \"int\", 15]")
    HAROS_COSTMAP_PARAM("[\"mark_threshold\", \"int\", 0]")
    HAROS_COSTMAP_PARAM("[\"combination_method\", \"int\", 1]") VoxelPluginConfig {
  bool enabled;
  bool footprint_clearing_enabled;
  double max_obstacle_height;
  double origin_z;
  double z_resolution;
  int z_voxels;
  int unknown_threshold;
  int mark_threshold;
  int combination_method;
  static const VoxelPluginConfig& __getDefault__();
};
struct HAROS_COSTMAP_CONFIG
    HAROS_COSTMAP_PARAM("[\"enabled\", \"bool\", true]")
    HAROS_COSTMAP_PARAM("[\"cost_scaling_factor\", \"double\", 10.0]")
    HAROS_COSTMAP_PARAM("[\"inflation_radius\", \"double\", 0.55]")
    HAROS_COSTMAP_PARAM("[\"inflate_unknown\", \"bool\", false]") InflationPluginConfig {
  bool enabled;
  double cost_scaling_factor;
  double inflation_radius;
  bool inflate_unknown;
  static const InflationPluginConfig& __getDefault__();
};
// the costmap node's own config (Costmap2D.cfg): its fields, for code that reads one
struct Costmap2DConfig {
  double transform_tolerance;
  double update_frequency;
  double publish_frequency;
  std::string global_frame;
  std::string robot_base_frame;
  std::string footprint;
  double robot_radius;
  double footprint_padding;
  int width;
  int height;
  double resolution;
  double origin_x;
  double origin_y;
  static const Costmap2DConfig& __getDefault__();
};

// costmap_2d.h: a grid of costs (no ROS call)
class Costmap2D {
public:
  Costmap2D(unsigned int cells_size_x, unsigned int cells_size_y, double resolution,
            double origin_x, double origin_y, unsigned char default_value = 0);
  Costmap2D(const Costmap2D& map);
  Costmap2D& operator=(const Costmap2D& map);
  Costmap2D();
  virtual ~Costmap2D();
  bool copyCostmapWindow(const Costmap2D& map, double win_origin_x, double win_origin_y,
                         double win_size_x, double win_size_y);
  unsigned char getCost(unsigned int mx, unsigned int my) const;
  void setCost(unsigned int mx, unsigned int my, unsigned char cost);
  void mapToWorld(unsigned int mx, unsigned int my, double& wx, double& wy) const;
  bool worldToMap(double wx, double wy, unsigned int& mx, unsigned int& my) const;
  void worldToMapNoBounds(double wx, double wy, int& mx, int& my) const;
  void worldToMapEnforceBounds(double wx, double wy, int& mx, int& my) const;
  unsigned int getIndex(unsigned int mx, unsigned int my) const;
  void indexToCells(unsigned int index, unsigned int& mx, unsigned int& my) const;
  unsigned char* getCharMap() const;
  unsigned int getSizeInCellsX() const;
  unsigned int getSizeInCellsY() const;
  double getSizeInMetersX() const;
  double getSizeInMetersY() const;
  double getOriginX() const;
  double getOriginY() const;
  double getResolution() const;
  void setDefaultValue(unsigned char c);
  unsigned char getDefaultValue();
  bool setConvexPolygonCost(const std::vector<geometry_msgs::Point>& polygon,
                            unsigned char cost_value);
  void polygonOutlineCells(const std::vector<MapLocation>& polygon,
                           std::vector<MapLocation>& polygon_cells);
  void convexFillCells(const std::vector<MapLocation>& polygon,
                       std::vector<MapLocation>& polygon_cells);
  virtual void updateOrigin(double new_origin_x, double new_origin_y);
  bool saveMap(std::string file_name);
  void resizeMap(unsigned int size_x, unsigned int size_y, double resolution, double origin_x,
                 double origin_y);
  void resetMap(unsigned int x0, unsigned int y0, unsigned int xn, unsigned int yn);
  unsigned int cellDistance(double world_dist);
  typedef boost::recursive_mutex mutex_t;
  mutex_t* getMutex();
protected:
  template<typename data_type>
  void copyMapRegion(data_type* source_map, unsigned int sm_lower_left_x,
                     unsigned int sm_lower_left_y, unsigned int sm_size_x, data_type* dest_map,
                     unsigned int dm_lower_left_x, unsigned int dm_lower_left_y,
                     unsigned int dm_size_x, unsigned int region_size_x,
                     unsigned int region_size_y);
  virtual void deleteMaps();
  virtual void resetMaps();
  virtual void initMaps(unsigned int size_x, unsigned int size_y);
  template<class ActionType>
  void raytraceLine(ActionType at, unsigned int x0, unsigned int y0, unsigned int x1,
                    unsigned int y1, unsigned int max_length = 4294967295u);
  mutex_t* access_;
  unsigned int size_x_;
  unsigned int size_y_;
  double resolution_;
  double origin_x_;
  double origin_y_;
  unsigned char* costmap_;
  unsigned char default_value_;
  class MarkCell {
  public:
    MarkCell(unsigned char* costmap, unsigned char value);
    void operator()(unsigned int offset);
  };
};

class Layer;

// layered_costmap.h: the layers and their combined grid (no ROS call)
class LayeredCostmap {
public:
  LayeredCostmap(std::string global_frame, bool rolling_window, bool track_unknown);
  ~LayeredCostmap();
  void updateMap(double robot_x, double robot_y, double robot_yaw);
  const std::string& getGlobalFrameID() const;
  void resizeMap(unsigned int size_x, unsigned int size_y, double resolution, double origin_x,
                 double origin_y, bool size_locked = false);
  void getUpdatedBounds(double& minx, double& miny, double& maxx, double& maxy);
  bool isCurrent();
  Costmap2D* getCostmap();
  bool isRolling();
  bool isTrackingUnknown();
  std::vector<boost::shared_ptr<Layer> >* getPlugins();
  void addPlugin(boost::shared_ptr<Layer> plugin);
  bool isSizeLocked();
  void getBounds(unsigned int* x0, unsigned int* xn, unsigned int* y0, unsigned int* yn);
  bool isInitialized();
  void setFootprint(const std::vector<geometry_msgs::Point>& footprint_spec);
  const std::vector<geometry_msgs::Point>& getFootprint();
  double getCircumscribedRadius();
  double getInscribedRadius();
};

// layer.h: a costmap plugin, initialised by its costmap with its name (move_base's
// ``<costmap>/<plugin name>``) and the tf2 buffer
class Layer {
public:
  Layer();
  void initialize(LayeredCostmap* parent, std::string name, tf2_ros::Buffer* tf);
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j);
  virtual void deactivate();
  virtual void activate();
  virtual void reset();
  virtual ~Layer();
  bool isCurrent() const;
  bool isEnabled() const;
  virtual void matchSize();
  const std::string& getName() const;
  const std::vector<geometry_msgs::Point>& getFootprint() const;
  virtual void onFootprintChanged();
protected:
  virtual void onInitialize();
  LayeredCostmap* layered_costmap_;
  bool current_;
  bool enabled_;
  std::string name_;
  tf2_ros::Buffer* tf_;
};

// costmap_layer.h: a layer with a grid of its own
class CostmapLayer : public Layer, public Costmap2D {
public:
  CostmapLayer();
  bool isDiscretized();
  virtual void matchSize();
  virtual void clearArea(int start_x, int start_y, int end_x, int end_y,
                         bool invert_area = false);
  void addExtraBounds(double mx0, double my0, double mx1, double my1);
protected:
  void updateWithTrueOverwrite(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                               int max_j);
  void updateWithOverwrite(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void updateWithMax(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void updateWithAddition(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void touch(double x, double y, double* min_x, double* min_y, double* max_x, double* max_y);
  void useExtraBounds(double* min_x, double* min_y, double* max_x, double* max_y);
  bool has_extra_bounds_;
};

// observation.h: a sensor's points and where they were seen from (no ROS call)
class Observation {
public:
  Observation();
  virtual ~Observation();
  Observation(geometry_msgs::Point& origin, const sensor_msgs::PointCloud2& cloud,
              double obstacle_range, double raytrace_range);
  Observation(const Observation& obs);
  Observation(const sensor_msgs::PointCloud2& cloud, double obstacle_range);
  geometry_msgs::Point origin_;
  sensor_msgs::PointCloud2* cloud_;
  double obstacle_range_, raytrace_range_;
};

// observation_buffer.h: a sensor's recent observations in the global frame (no ROS call)
class ObservationBuffer {
public:
  // noetic's takes a tf2 buffer, kinetic's a tf listener: any
  template<class Tf>
  ObservationBuffer(std::string topic_name, double observation_keep_time,
                    double expected_update_rate, double min_obstacle_height,
                    double max_obstacle_height, double obstacle_range, double raytrace_range,
                    Tf& tf2_buffer, std::string global_frame,
                    std::string sensor_frame, double tf_tolerance);
  ~ObservationBuffer();
  bool setGlobalFrame(const std::string new_global_frame);
  void bufferCloud(const sensor_msgs::PointCloud2& cloud);
  void getObservations(std::vector<Observation>& observations);
  bool isCurrent() const;
  void lock();
  void unlock();
  void resetLastUpdated();
};

// obstacle_layer.h: the layer that marks and clears from its observation sources; a
// plugin derived from it (fetch's depth layer, through VoxelLayer) runs its onInitialize,
// whose subscriptions the plugin attachment describes (plugins.hosts.SOURCES)
class ObstacleLayer : public CostmapLayer {
public:
  ObstacleLayer();
  virtual ~ObstacleLayer();
  virtual void onInitialize();
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j);
  virtual void activate();
  virtual void deactivate();
  virtual void reset();
  void laserScanCallback(const sensor_msgs::LaserScanConstPtr& message,
                         const boost::shared_ptr<ObservationBuffer>& buffer);
  void laserScanValidInfCallback(const sensor_msgs::LaserScanConstPtr& message,
                                 const boost::shared_ptr<ObservationBuffer>& buffer);
  void pointCloudCallback(const sensor_msgs::PointCloudConstPtr& message,
                          const boost::shared_ptr<ObservationBuffer>& buffer);
  void pointCloud2Callback(const sensor_msgs::PointCloud2ConstPtr& message,
                           const boost::shared_ptr<ObservationBuffer>& buffer);
  void addStaticObservation(Observation& obs, bool marking, bool clearing);
  void clearStaticObservations(bool marking, bool clearing);
protected:
  virtual void setupDynamicReconfigure(ros::NodeHandle& nh);
  bool getMarkingObservations(std::vector<Observation>& marking_observations) const;
  bool getClearingObservations(std::vector<Observation>& clearing_observations) const;
  virtual void raytraceFreespace(const Observation& clearing_observation, double* min_x,
                                 double* min_y, double* max_x, double* max_y);
  void updateRaytraceBounds(double ox, double oy, double wx, double wy, double range,
                            double* min_x, double* min_y, double* max_x, double* max_y);
  void updateFootprint(double robot_x, double robot_y, double robot_yaw, double* min_x,
                       double* min_y, double* max_x, double* max_y);
  std::vector<geometry_msgs::Point> transformed_footprint_;
  bool footprint_clearing_enabled_;
  std::string global_frame_;
  double max_obstacle_height_;
  laser_geometry::LaserProjection projector_;
  std::vector<boost::shared_ptr<message_filters::haros_subscriber_base> > observation_subscribers_;
  std::vector<boost::shared_ptr<tf2_ros::MessageFilterBase> > observation_notifiers_;
  std::vector<boost::shared_ptr<ObservationBuffer> > observation_buffers_;
  std::vector<boost::shared_ptr<ObservationBuffer> > marking_buffers_;
  std::vector<boost::shared_ptr<ObservationBuffer> > clearing_buffers_;
  std::vector<Observation> static_clearing_observations_, static_marking_observations_;
  bool rolling_window_;
  dynamic_reconfigure::Server<ObstaclePluginConfig>* dsrv_;
  int combination_method_;
};

// voxel_layer.h: an obstacle layer over a 3D grid (its onInitialize runs ObstacleLayer's)
class VoxelLayer : public ObstacleLayer {
public:
  VoxelLayer();
  virtual ~VoxelLayer();
  virtual void onInitialize();
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  void updateOrigin(double new_origin_x, double new_origin_y);
  bool isDiscretized();
  virtual void matchSize();
  virtual void reset();
protected:
  virtual void setupDynamicReconfigure(ros::NodeHandle& nh);
  virtual void resetMaps();
};

// static_layer.h: the map a map server publishes
class StaticLayer : public CostmapLayer {
public:
  StaticLayer();
  virtual ~StaticLayer();
  virtual void onInitialize();
  virtual void activate();
  virtual void deactivate();
  virtual void reset();
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j);
  virtual void matchSize();
};

// inflation_layer.h: costs spread from lethal cells
class CellData {
public:
  CellData(double i, unsigned int x, unsigned int y, unsigned int sx, unsigned int sy);
  unsigned int index_;
  unsigned int x_, y_;
  unsigned int src_x_, src_y_;
};
class InflationLayer : public Layer {
public:
  InflationLayer();
  virtual ~InflationLayer();
  virtual void onInitialize();
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j);
  virtual bool isDiscretized();
  virtual void matchSize();
  virtual void reset();
  virtual unsigned char computeCost(double distance) const;
  void setInflationParameters(double inflation_radius, double cost_scaling_factor);
protected:
  virtual void onFootprintChanged();
  boost::recursive_mutex* inflation_access_;
  double resolution_;
  double inflation_radius_;
  double inscribed_radius_;
  double weight_;
  bool inflate_unknown_;
};

// footprint.h: the functions that read or write no parameter
void calculateMinAndMaxDistances(const std::vector<geometry_msgs::Point>& footprint,
                                 double& min_dist, double& max_dist);
geometry_msgs::Point toPoint(geometry_msgs::Point32 pt);
geometry_msgs::Point32 toPoint32(geometry_msgs::Point pt);
geometry_msgs::Polygon toPolygon(std::vector<geometry_msgs::Point> pts);
std::vector<geometry_msgs::Point> toPointVector(geometry_msgs::Polygon polygon);
void transformFootprint(double x, double y, double theta,
                        const std::vector<geometry_msgs::Point>& footprint_spec,
                        std::vector<geometry_msgs::Point>& oriented_footprint);
void transformFootprint(double x, double y, double theta,
                        const std::vector<geometry_msgs::Point>& footprint_spec,
                        geometry_msgs::PolygonStamped& oriented_footprint);
void padFootprint(std::vector<geometry_msgs::Point>& footprint, double padding);
std::vector<geometry_msgs::Point> makeFootprintFromRadius(double radius);
bool makeFootprintFromString(const std::string& footprint_string,
                             std::vector<geometry_msgs::Point>& footprint);

// array_parser.h
std::vector<std::vector<float> > parseVVF(const std::string& input, std::string& error_return);

// costmap_2d_ros.h: the costmap node's wrapper, which reads its parameters, loads its
// layers and publishes under its name; what it does is not described (HAROS_UNREAD)
class HAROS_UNREAD Costmap2DROS {
public:
  // noetic's takes a tf2 buffer, kinetic's a tf listener: any
  template<class Tf> Costmap2DROS(const std::string& name, Tf&& tf);
  ~Costmap2DROS();
  void start();
  void stop();
  void pause();
  void resume();
  void updateMap();
  void resetLayers();
  bool isCurrent() const;
  bool isStopped() const;
  bool getRobotPose(geometry_msgs::PoseStamped& global_pose) const;
  const std::string& getName() const;
  double getTransformTolerance() const;
  Costmap2D* getCostmap() const;
  const std::string& getGlobalFrameID() const;
  const std::string& getBaseFrameID() const;
  LayeredCostmap* getLayeredCostmap() const;
  geometry_msgs::Polygon getRobotFootprintPolygon() const;
  const std::vector<geometry_msgs::Point>& getRobotFootprint() const;
  const std::vector<geometry_msgs::Point>& getUnpaddedRobotFootprint() const;
  void getOrientedFootprint(std::vector<geometry_msgs::Point>& oriented_footprint) const;
  void setUnpaddedRobotFootprint(const std::vector<geometry_msgs::Point>& points);
  void setUnpaddedRobotFootprintPolygon(const geometry_msgs::Polygon& footprint);
};

// costmap_2d_publisher.h: publishes a grid (and its updates) on the handle it is given
class HAROS_UNREAD Costmap2DPublisher {
public:
  Costmap2DPublisher(ros::NodeHandle* ros_node, Costmap2D* costmap, std::string global_frame,
                     std::string topic_name, bool always_send_full_costmap = false);
  ~Costmap2DPublisher();
  void updateBounds(unsigned int x0, unsigned int xn, unsigned int y0, unsigned int yn);
  void publishCostmap();
  bool active();
};

}  // namespace costmap_2d
#undef HAROS_COSTMAP_CONFIG
#undef HAROS_COSTMAP_PARAM
#endif
