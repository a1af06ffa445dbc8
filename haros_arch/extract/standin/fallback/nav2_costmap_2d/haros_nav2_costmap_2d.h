// haros_arch stand-in: the parts of navigation2's nav2_costmap_2d that plugins outside
// navigation2 use (declarations only; every nav2_costmap_2d/... header stands in as this
// one, read only when the workspace has no nav2_costmap_2d package,
// headers.FALLBACK_UMBRELLAS). Humble's and Jazzy's API beside Kilted's: a layer's node
// is the Kilted lifecycle node, whose pointer converts to the older one. A layer's
// declareParameter(name, value) declares ``<the layer's name>.name`` on its node (an API
// row; the layer's name is given at run time, so ``?.name``). FootprintSubscriber's
// subscription is a row; the classes that subscribe or publish on the node they are
// given in ways that differ between releases (CostmapSubscriber,
// CostmapTopicCollisionChecker, Costmap2DPublisher) are declared HAROS_UNREAD: what they
// make is not described, and a node given to one is partial (CPP_NODE_TO_UNKNOWN).
#ifndef HAROS_STANDIN_NAV2_COSTMAP_2D_H
#define HAROS_STANDIN_NAV2_COSTMAP_2D_H
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <tf2_ros/buffer.h>
#include <nav2_util/lifecycle_node.hpp>
#include <nav2_ros_common/lifecycle_node.hpp>
#include <list>
#include <laser_geometry/laser_geometry.hpp>
#include <message_filters/subscriber.h>
#include <tf2_ros/message_filter.h>
#include <geometry_msgs/msg/point.hpp>
#include <geometry_msgs/msg/point32.hpp>
#include <geometry_msgs/msg/polygon.hpp>
#include <geometry_msgs/msg/polygon_stamped.hpp>
#include <geometry_msgs/msg/pose2_d.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>
#include <nav_msgs/msg/occupancy_grid.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>
#include <sensor_msgs/msg/point_cloud2.hpp>
#include <std_msgs/msg/header.hpp>
#ifndef HAROS_UNREAD
#define HAROS_UNREAD __attribute__((annotate("haros_unread")))
#endif

namespace nav2_costmap_2d {

// cost_values.hpp
enum class CombinationMethod : int { Overwrite = 0, Max = 1, MaxWithoutUnknownOverwrite = 2 };
static constexpr unsigned char NO_INFORMATION = 255;
static constexpr unsigned char LETHAL_OBSTACLE = 254;
static constexpr unsigned char INSCRIBED_INFLATED_OBSTACLE = 253;
static constexpr unsigned char MAX_NON_OBSTACLE = 252;
static constexpr unsigned char FREE_SPACE = 0;
static constexpr double NO_SPEED_LIMIT = 0.0;

typedef std::vector<geometry_msgs::msg::Point> Footprint;

struct MapLocation { unsigned int x; unsigned int y; unsigned char cost; };

// costmap_2d.hpp: a grid of costs (no ROS call)
class Costmap2D {
public:
  Costmap2D(unsigned int cells_size_x, unsigned int cells_size_y, double resolution,
            double origin_x, double origin_y, unsigned char default_value = 0);
  Costmap2D(const Costmap2D& map);
  explicit Costmap2D(const nav_msgs::msg::OccupancyGrid& map);
  Costmap2D& operator=(const Costmap2D& map);
  Costmap2D();
  virtual ~Costmap2D();
  bool copyCostmapWindow(const Costmap2D& map, double win_origin_x, double win_origin_y,
                         double win_size_x, double win_size_y);
  bool copyWindow(const Costmap2D& source, unsigned int sx0, unsigned int sy0,
                  unsigned int sxn, unsigned int syn, unsigned int dx0, unsigned int dy0);
  unsigned char getCost(unsigned int mx, unsigned int my) const;
  unsigned char getCost(unsigned int index) const;
  void setCost(unsigned int mx, unsigned int my, unsigned char cost);
  void mapToWorld(unsigned int mx, unsigned int my, double& wx, double& wy) const;
  void mapToWorldNoBounds(int mx, int my, double& wx, double& wy) const;
  bool worldToMap(double wx, double wy, unsigned int& mx, unsigned int& my) const;
  bool worldToMapContinuous(double wx, double wy, float& mx, float& my) const;
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
  bool setConvexPolygonCost(const std::vector<geometry_msgs::msg::Point>& polygon,
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
  void resetMapToValue(unsigned int x0, unsigned int y0, unsigned int xn, unsigned int yn,
                       unsigned char value);
  unsigned int cellDistance(double world_dist);
  typedef std::recursive_mutex mutex_t;
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
                    unsigned int y1, unsigned int max_length = 4294967295u,
                    unsigned int min_length = 0);
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

// layered_costmap.hpp: the layers and their combined grid (no ROS call)
class LayeredCostmap {
public:
  LayeredCostmap(std::string global_frame, bool rolling_window, bool track_unknown);
  ~LayeredCostmap();
  void updateMap(double robot_x, double robot_y, double robot_yaw);
  std::string getGlobalFrameID() const;
  void resizeMap(unsigned int size_x, unsigned int size_y, double resolution, double origin_x,
                 double origin_y, bool size_locked = false);
  void getUpdatedBounds(double& minx, double& miny, double& maxx, double& maxy);
  bool isCurrent();
  Costmap2D* getCostmap();
  bool isRolling();
  bool isTrackingUnknown();
  std::vector<std::shared_ptr<Layer>>* getPlugins();
  std::vector<std::shared_ptr<Layer>>* getFilters();
  void addPlugin(std::shared_ptr<Layer> plugin);
  void addFilter(std::shared_ptr<Layer> filter);
  bool isSizeLocked();
  void getBounds(unsigned int* x0, unsigned int* xn, unsigned int* y0, unsigned int* yn);
  bool isInitialized();
  void setFootprint(const std::vector<geometry_msgs::msg::Point>& footprint_spec);
  const std::vector<geometry_msgs::msg::Point>& getFootprint();
  double getCircumscribedRadius();
  double getInscribedRadius();
  bool isOutofBounds(double robot_x, double robot_y);
};

// layer.hpp: a costmap plugin, initialised by its costmap with its name and node
class Layer {
public:
  Layer();
  virtual ~Layer();
  void initialize(LayeredCostmap* parent, std::string name, tf2_ros::Buffer* tf,
                  const nav2::LifecycleNode::WeakPtr& node,
                  rclcpp::CallbackGroup::SharedPtr callback_group);
  void initialize(LayeredCostmap* parent, std::string name, tf2_ros::Buffer* tf,
                  const rclcpp_lifecycle::LifecycleNode::WeakPtr& node,
                  rclcpp::CallbackGroup::SharedPtr callback_group);
  virtual void deactivate();
  virtual void activate();
  virtual void reset() = 0;
  virtual bool isClearable() = 0;
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y) = 0;
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j) = 0;
  virtual void matchSize();
  virtual void onFootprintChanged();
  std::string getName() const;
  bool isCurrent() const;
  void setCurrent(bool current);
  bool isEnabled() const;
  const std::vector<geometry_msgs::msg::Point>& getFootprint() const;
  // declares ``<name_>.param_name`` on node_ unless it is already (Humble, Jazzy; an
  // API row)
  void declareParameter(const std::string& param_name, const rclcpp::ParameterValue& value);
  void declareParameter(const std::string& param_name, const rclcpp::ParameterType& param_type);
  bool hasParameter(const std::string& param_name);
  std::string getFullName(const std::string& param_name);
  std::string joinWithParentNamespace(const std::string& topic);
protected:
  LayeredCostmap* layered_costmap_;
  std::string name_;
  tf2_ros::Buffer* tf_;
  rclcpp::CallbackGroup::SharedPtr callback_group_;
  // the node the costmap gives it: Kilted's nav2 lifecycle node from Kilted on (rclcpp
  // 29), rclcpp_lifecycle's before, as each release's layer.hpp has it (an unqualified
  // call on ``node_.lock()`` looks in the namespace of its class: cabot-navigation's
  // Humble layer calls ``declare_parameter_if_not_declared(node, ...)`` of nav2_util)
#if RCLCPP_VERSION_MAJOR >= 29
  nav2::LifecycleNode::WeakPtr node_;
#else
  rclcpp_lifecycle::LifecycleNode::WeakPtr node_;
#endif
  rclcpp::Clock::SharedPtr clock_;
  rclcpp::Logger logger_;
  virtual void onInitialize();
  bool current_;
  bool enabled_;
};

// costmap_layer.hpp: a layer with a grid of its own
class CostmapLayer : public Layer, public Costmap2D {
public:
  CostmapLayer();
  bool isDiscretized();
  virtual void matchSize();
  virtual void clearArea(int start_x, int start_y, int end_x, int end_y, bool invert);
  void addExtraBounds(double mx0, double my0, double mx1, double my1);
protected:
  void updateWithTrueOverwrite(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                               int max_j);
  void updateWithOverwrite(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void updateWithMax(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void updateWithMaxWithoutUnknownOverwrite(Costmap2D& master_grid, int min_i, int min_j,
                                            int max_i, int max_j);
  void updateWithAddition(Costmap2D& master_grid, int min_i, int min_j, int max_i, int max_j);
  void touch(double x, double y, double* min_x, double* min_y, double* max_x, double* max_y);
  void useExtraBounds(double* min_x, double* min_y, double* max_x, double* max_y);
  bool has_extra_bounds_;
  CombinationMethod combination_method_from_int(const int value);
};

// observation.hpp: a sensor's points and where they were seen from (no ROS call). Its
// cloud is a pointer until Jazzy and a value from Kilted on: one that reads as either
// (``obs.cloud_->width``, ``*obs.cloud_``, ``obs.cloud_.width``)
struct haros_observed_cloud : sensor_msgs::msg::PointCloud2 {
  haros_observed_cloud();
  haros_observed_cloud(const sensor_msgs::msg::PointCloud2& cloud);
  haros_observed_cloud(sensor_msgs::msg::PointCloud2* cloud);
  const sensor_msgs::msg::PointCloud2* operator->() const;
  sensor_msgs::msg::PointCloud2* operator->();
  const sensor_msgs::msg::PointCloud2& operator*() const;
  sensor_msgs::msg::PointCloud2& operator*();
};
class Observation {
public:
  using SharedPtr = std::shared_ptr<Observation>;
  using ConstSharedPtr = std::shared_ptr<const Observation>;
  Observation();
  Observation(geometry_msgs::msg::Point origin, sensor_msgs::msg::PointCloud2 cloud,
              double obstacle_max_range, double obstacle_min_range,
              double raytrace_max_range, double raytrace_min_range);
  Observation(const sensor_msgs::msg::PointCloud2& cloud, double obstacle_max_range,
              double obstacle_min_range);
  geometry_msgs::msg::Point origin_;
  haros_observed_cloud cloud_;
  double obstacle_max_range_;
  double obstacle_min_range_;
  double raytrace_max_range_;
  double raytrace_min_range_;
};

// observation_buffer.hpp: a sensor's recent observations, in the global frame; its node
// gives it a clock and a logger only (the buffer type and the node's differ between
// releases: any)
class ObservationBuffer {
public:
  template<class NodeT, class BufferT>
  ObservationBuffer(const NodeT& parent, std::string topic_name, double observation_keep_time,
                    double expected_update_rate, double min_obstacle_height,
                    double max_obstacle_height, double obstacle_max_range,
                    double obstacle_min_range, double raytrace_max_range,
                    double raytrace_min_range, BufferT& tf2_buffer, std::string global_frame,
                    std::string sensor_frame, tf2::Duration tf_tolerance);
  void bufferCloud(const sensor_msgs::msg::PointCloud2& cloud);
  // the observations as values until Jazzy, as shared pointers from Kilted on
  void getObservations(std::vector<Observation>& observations);
  void getObservations(std::vector<Observation::ConstSharedPtr>& observations);
  bool isCurrent() const;
  void lock();
  void unlock();
  void resetLastUpdated();
};

// obstacle_layer.hpp: the layer that marks and clears from its observation sources; a
// plugin derived from it (rtabmap's VoxelLayer) runs its onInitialize, whose
// subscriptions the plugin attachment describes (plugins.hosts.SOURCES)
class ObstacleLayer : public CostmapLayer {
public:
  ObstacleLayer();
  virtual ~ObstacleLayer();
  virtual void onInitialize();
  virtual void updateBounds(double robot_x, double robot_y, double robot_yaw, double* min_x,
                            double* min_y, double* max_x, double* max_y);
  virtual void updateCosts(Costmap2D& master_grid, int min_i, int min_j, int max_i,
                           int max_j);
  virtual void deactivate();
  virtual void activate();
  virtual void reset();
  virtual bool isClearable();
  rcl_interfaces::msg::SetParametersResult dynamicParametersCallback(
    std::vector<rclcpp::Parameter> parameters);
  rcl_interfaces::msg::SetParametersResult validateParameterUpdatesCallback(
    const std::vector<rclcpp::Parameter>& parameters);
  void updateParametersCallback(const std::vector<rclcpp::Parameter>& parameters);
  void resetBuffersLastUpdated();
  void laserScanCallback(sensor_msgs::msg::LaserScan::ConstSharedPtr message,
                         const std::shared_ptr<ObservationBuffer>& buffer);
  void laserScanValidInfCallback(sensor_msgs::msg::LaserScan::ConstSharedPtr message,
                                 const std::shared_ptr<ObservationBuffer>& buffer);
  void pointCloud2Callback(sensor_msgs::msg::PointCloud2::ConstSharedPtr message,
                           const std::shared_ptr<ObservationBuffer>& buffer);
  void addStaticObservation(Observation obs, bool marking, bool clearing);
  void clearStaticObservations(bool marking, bool clearing);
protected:
  bool getMarkingObservations(std::vector<Observation>& marking_observations) const;
  bool getMarkingObservations(
    std::vector<Observation::ConstSharedPtr>& marking_observations) const;
  bool getClearingObservations(std::vector<Observation>& clearing_observations) const;
  bool getClearingObservations(
    std::vector<Observation::ConstSharedPtr>& clearing_observations) const;
  virtual void raytraceFreespace(const Observation& clearing_observation, double* min_x,
                                 double* min_y, double* max_x, double* max_y);
  void updateRaytraceBounds(double ox, double oy, double wx, double wy, double max_range,
                            double min_range, double* min_x, double* min_y, double* max_x,
                            double* max_y);
  void updateFootprint(double robot_x, double robot_y, double robot_yaw, double* min_x,
                       double* min_y, double* max_x, double* max_y);
  std::vector<geometry_msgs::msg::Point> transformed_footprint_;
  bool footprint_clearing_enabled_;
  std::string global_frame_;
  double min_obstacle_height_;
  double max_obstacle_height_;
  laser_geometry::LaserProjection projector_;
  std::vector<std::shared_ptr<message_filters::haros_subscriber_base>> observation_subscribers_;
  std::vector<std::shared_ptr<tf2_ros::MessageFilterBase>> observation_notifiers_;
  std::vector<std::shared_ptr<ObservationBuffer>> observation_buffers_;
  std::vector<std::shared_ptr<ObservationBuffer>> marking_buffers_;
  std::vector<std::shared_ptr<ObservationBuffer>> clearing_buffers_;
  // Humble's and Jazzy's handler, then Kilted's two
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr dyn_params_handler_;
  rclcpp::node_interfaces::PostSetParametersCallbackHandle::SharedPtr post_set_params_handler_;
  rclcpp::node_interfaces::OnSetParametersCallbackHandle::SharedPtr on_set_params_handler_;
  std::vector<Observation::ConstSharedPtr> static_clearing_observations_;
  std::vector<Observation::ConstSharedPtr> static_marking_observations_;
  bool rolling_window_;
  bool was_reset_;
  CombinationMethod combination_method_;
  bool allow_parameter_qos_overrides_;
};

// footprint.hpp
std::pair<double, double> calculateMinAndMaxDistances(
  const std::vector<geometry_msgs::msg::Point>& footprint);
geometry_msgs::msg::Point toPoint(geometry_msgs::msg::Point32 pt);
geometry_msgs::msg::Point32 toPoint32(geometry_msgs::msg::Point pt);
geometry_msgs::msg::Polygon toPolygon(std::vector<geometry_msgs::msg::Point> pts);
std::vector<geometry_msgs::msg::Point> toPointVector(
  geometry_msgs::msg::Polygon::SharedPtr polygon);
std::vector<geometry_msgs::msg::Point> toPointVector(const geometry_msgs::msg::Polygon& polygon);
void transformFootprint(double x, double y, double theta,
                        const std::vector<geometry_msgs::msg::Point>& footprint_spec,
                        std::vector<geometry_msgs::msg::Point>& oriented_footprint);
void transformFootprint(double x, double y, double theta,
                        const std::vector<geometry_msgs::msg::Point>& footprint_spec,
                        geometry_msgs::msg::PolygonStamped& oriented_footprint);
void padFootprint(std::vector<geometry_msgs::msg::Point>& footprint, double padding);
std::vector<geometry_msgs::msg::Point> makeFootprintFromRadius(double radius);
bool makeFootprintFromString(const std::string& footprint_string,
                             std::vector<geometry_msgs::msg::Point>& footprint);

// footprint_collision_checker.hpp: costs of a footprint on a grid (no ROS call)
template<typename CostmapT>
class FootprintCollisionChecker {
public:
  FootprintCollisionChecker();
  explicit FootprintCollisionChecker(CostmapT costmap);
  double footprintCost(const Footprint& footprint);
  double footprintCostAtPose(double x, double y, double theta, const Footprint& footprint);
  double lineCost(int x0, int x1, int y0, int y1) const;
  bool worldToMap(double wx, double wy, unsigned int& mx, unsigned int& my);
  double pointCost(int x, int y) const;
  void setCostmap(CostmapT costmap);
  CostmapT getCostmap();
};

// costmap_2d_ros.hpp: the costmap node a planner or controller is given
class Costmap2DROS : public nav2::LifecycleNode {
public:
  explicit Costmap2DROS(const rclcpp::NodeOptions& options = rclcpp::NodeOptions());
  explicit Costmap2DROS(const std::string& name, const bool& use_sim_time = false);
  explicit Costmap2DROS(const std::string& name, const std::string& parent_namespace,
                        const std::string& local_namespace, const bool& use_sim_time);
  ~Costmap2DROS();
  void start();
  void stop();
  void pause();
  void resume();
  void updateMap();
  void resetLayers();
  bool isCurrent();
  void waitUntilCurrent(const rclcpp::Duration& timeout);
  bool getRobotPose(geometry_msgs::msg::PoseStamped& global_pose);
  bool transformPoseToGlobalFrame(const geometry_msgs::msg::PoseStamped& input_pose,
                                  geometry_msgs::msg::PoseStamped& transformed_pose);
  std::string getName() const;
  double getTransformTolerance() const;
  Costmap2D* getCostmap();
  std::string getGlobalFrameID();
  std::string getBaseFrameID();
  LayeredCostmap* getLayeredCostmap();
  geometry_msgs::msg::Polygon getRobotFootprintPolygon();
  std::vector<geometry_msgs::msg::Point> getRobotFootprint();
  std::vector<geometry_msgs::msg::Point> getUnpaddedRobotFootprint();
  void getOrientedFootprint(std::vector<geometry_msgs::msg::Point>& oriented_footprint);
  void setRobotFootprint(const std::vector<geometry_msgs::msg::Point>& points);
  std::shared_ptr<tf2_ros::Buffer> getTfBuffer();
  bool getUseRadius();
  double getRobotRadius();
};

// subscribe or publish on the node they are given: not described (HAROS_UNREAD)
class HAROS_UNREAD CostmapSubscriber {
public:
  template<typename... Args> explicit CostmapSubscriber(Args&&... args);
  std::shared_ptr<Costmap2D> getCostmap();
  bool isCostmapReceived();
};
// subscribes to the robot's footprint on topic_name (an API row)
class FootprintSubscriber {
public:
  template<typename NodeT>
  FootprintSubscriber(const NodeT& parent, const std::string& topic_name, tf2_ros::Buffer& tf,
                      std::string robot_base_frame = "base_link",
                      double transform_tolerance = 0.1);
  bool getFootprintRaw(std::vector<geometry_msgs::msg::Point>& footprint,
                       std_msgs::msg::Header& footprint_header);
  bool getFootprintInRobotFrame(std::vector<geometry_msgs::msg::Point>& footprint,
                                std_msgs::msg::Header& footprint_header);
};
class HAROS_UNREAD CostmapTopicCollisionChecker {
public:
  template<typename... Args> explicit CostmapTopicCollisionChecker(Args&&... args);
  double scorePose(const geometry_msgs::msg::Pose2D& pose, bool fetch_costmap_and_footprint = true);
  bool isCollisionFree(const geometry_msgs::msg::Pose2D& pose,
                       bool fetch_costmap_and_footprint = true);
};
class HAROS_UNREAD Costmap2DPublisher {
public:
  template<typename... Args> explicit Costmap2DPublisher(Args&&... args);
  void on_configure();
  void on_activate();
  void on_deactivate();
  void on_cleanup();
  void publishCostmap();
  bool active();
  void updateBounds(unsigned int x0, unsigned int xn, unsigned int y0, unsigned int yn);
};

}  // namespace nav2_costmap_2d
#endif
