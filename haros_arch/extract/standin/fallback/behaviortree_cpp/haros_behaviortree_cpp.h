// haros_arch stand-in: BehaviorTree.CPP (declarations only), the behaviour-tree library of
// navigation2 and of many ROS 2 robots, for a workspace that has it installed, not as
// sources: every `behaviortree_cpp/...` (version 4) and `behaviortree_cpp_v3/...` header
// stands in as this one (`headers.FALLBACK_UMBRELLAS`). The library ticks trees of nodes
// and keeps their data on a blackboard: it makes no ROS call of its own (the ROS calls of
// a tree are its nodes', which the workspace writes). Version 4's names, with version 3's
// beside them where they differ (NodeConfiguration, Optional, tickRoot).
#ifndef HAROS_STANDIN_BEHAVIORTREE_CPP_H
#define HAROS_STANDIN_BEHAVIORTREE_CPP_H
#include <chrono>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace BT {
using StringView = std::string_view;
using TimePoint = std::chrono::high_resolution_clock::time_point;
using Duration = std::chrono::high_resolution_clock::duration;

enum class NodeStatus { IDLE = 0, RUNNING = 1, SUCCESS = 2, FAILURE = 3, SKIPPED = 4 };
enum class NodeType { UNDEFINED = 0, ACTION, CONDITION, CONTROL, DECORATOR, SUBTREE };
enum class PortDirection { INPUT, OUTPUT, INOUT };
std::string toStr(NodeStatus status, bool colored = false);
std::string toStr(NodeType type);
std::string toStr(PortDirection direction);
inline bool isStatusActive(const NodeStatus& status);
inline bool isStatusCompleted(const NodeStatus& status);

class BehaviorTreeException : public std::exception {
public:
  template<class... A> explicit BehaviorTreeException(const A&... message);
  const char* what() const noexcept override;
};
class LogicError : public BehaviorTreeException {
public:
  template<class... A> explicit LogicError(const A&... message);
};
class RuntimeError : public BehaviorTreeException {
public:
  template<class... A> explicit RuntimeError(const A&... message);
};
class TreeNode;
// an exception a node's tick threw, with the node it came from
class NodeExecutionError : public RuntimeError {
public:
  struct FailedNodeInfo {
    std::string node_name;
    std::string node_path;
    std::string registration_name;
  };
  const FailedNodeInfo& failedNode() const;
  const std::string& originalMessage() const;
};

// a value or why there is none (nonstd::expected in the library)
template<class T> class Expected {
public:
  Expected();
  Expected(const T& value);
  explicit operator bool() const;
  bool has_value() const;
  T& value();
  const T& value() const;
  template<class U> T value_or(U&& other) const;
  const std::string& error() const;
  T& operator*();
  const T& operator*() const;
  T* operator->();
  const T* operator->() const;
};
struct haros_ok {};
using Result = Expected<haros_ok>;
template<class T> using Optional = Expected<T>;  // version 3's name

// a string written in the tree's XML to a value of a port's type
template<typename T> T convertFromString(StringView str);
template<typename T> T convertFromJSON(StringView json);
template<typename T> std::string toStr(const T& value);
std::vector<StringView> splitString(const StringView& text, char delimiter);
bool StartWith(StringView str, StringView prefix);
bool StartWith(StringView str, char prefix);
template<typename T> void RegisterJsonDefinition();

struct AnyTypeAllowed {};
class PortInfo {
public:
  PortInfo(PortDirection direction = PortDirection::INOUT);
  PortDirection direction() const;
  const std::string& description() const;
  template<class T> void setDefaultValue(const T& value);
};
using PortsList = std::unordered_map<std::string, PortInfo>;
using PortsRemapping = std::unordered_map<std::string, std::string>;
template<typename T = AnyTypeAllowed>
std::pair<std::string, PortInfo> InputPort(StringView name, StringView description = {});
template<typename T = AnyTypeAllowed, typename D = T>
std::pair<std::string, PortInfo> InputPort(StringView name, const D& default_value,
                                           StringView description);
template<typename T = AnyTypeAllowed>
std::pair<std::string, PortInfo> OutputPort(StringView name, StringView description = {});
template<typename T = AnyTypeAllowed, typename D = T>
std::pair<std::string, PortInfo> OutputPort(StringView name, const D& default_value,
                                            StringView description);
template<typename T = AnyTypeAllowed>
std::pair<std::string, PortInfo> BidirectionalPort(StringView name,
                                                   StringView description = {});

// the data a tree's nodes share, by key
class Blackboard {
public:
  using Ptr = std::shared_ptr<Blackboard>;
  static Ptr create(Ptr parent = {});
  template<typename T> bool get(const std::string& key, T& value) const;
  template<typename T> T get(const std::string& key) const;
  template<typename T> void set(const std::string& key, const T& value);
  void unset(const std::string& key);
  std::vector<StringView> getKeys() const;
  void clear();
  void addSubtreeRemapping(StringView internal, StringView external);
  void enableAutoRemapping(bool remapping);
  Ptr parent();
  void debugMessage() const;
};

struct TreeNodeManifest {
  NodeType type;
  std::string registration_ID;
  PortsList ports;
};
struct NodeConfig {
  NodeConfig();
  Blackboard::Ptr blackboard;
  std::shared_ptr<std::unordered_map<std::string, int>> enums;
  PortsRemapping input_ports;
  PortsRemapping output_ports;
  const TreeNodeManifest* manifest = nullptr;
  uint16_t uid = 0;
  std::string path;
};
using NodeConfiguration = NodeConfig;  // version 3's name

class TreeNode {
public:
  using Ptr = std::shared_ptr<TreeNode>;
  TreeNode(std::string name, NodeConfig config);
  virtual ~TreeNode();
  virtual NodeStatus executeTick();
  void haltNode();
  bool isHalted() const;
  NodeStatus status() const;
  const std::string& name() const;
  const std::string& registrationName() const;
  const std::string& fullPath() const;
  uint16_t UID() const;
  const NodeConfig& config() const;
  NodeConfig& config();
  virtual NodeType type() const = 0;
  template<typename T> Result getInput(const std::string& key, T& destination) const;
  template<typename T> Expected<T> getInput(const std::string& key) const;
  template<typename T> Result setOutput(const std::string& key, const T& value);
  static bool isBlackboardPointer(StringView str, StringView* stripped_pointer = nullptr);
  static StringView stripBlackboardPointer(StringView str);
  void emitWakeUpSignal();
  bool requiresWakeUp() const;
  virtual void halt() = 0;
protected:
  virtual NodeStatus tick() = 0;
  void resetStatus();
  void setStatus(NodeStatus new_status);
};
class LeafNode : public TreeNode {
public:
  LeafNode(const std::string& name, const NodeConfig& config);
};
class ActionNodeBase : public LeafNode {
public:
  ActionNodeBase(const std::string& name, const NodeConfig& config);
  NodeType type() const override final;
};
// ticked once, done at once: never RUNNING
class SyncActionNode : public ActionNodeBase {
public:
  SyncActionNode(const std::string& name, const NodeConfig& config);
  NodeStatus executeTick() override;
  void halt() override;
};
class SimpleActionNode : public SyncActionNode {
public:
  using TickFunctor = std::function<NodeStatus(TreeNode&)>;
  SimpleActionNode(const std::string& name, TickFunctor tick_functor, const NodeConfig& config);
protected:
  NodeStatus tick() override;
};
// started once, then ticked while RUNNING, or halted
class StatefulActionNode : public ActionNodeBase {
public:
  StatefulActionNode(const std::string& name, const NodeConfig& config);
  bool isHaltRequested() const;
  virtual NodeStatus onStart() = 0;
  virtual NodeStatus onRunning() = 0;
  virtual void onHalted() = 0;
  void halt() override;
protected:
  NodeStatus tick() override;
};
class CoroActionNode : public ActionNodeBase {
public:
  CoroActionNode(const std::string& name, const NodeConfig& config);
  void setStatusRunningAndYield();
  void halt() override;
  NodeStatus executeTick() override;
};
class ThreadedAction : public ActionNodeBase {
public:
  ThreadedAction(const std::string& name, const NodeConfig& config);
  bool isHaltRequested() const;
  void halt() override;
  NodeStatus executeTick() override;
};
class ConditionNode : public LeafNode {
public:
  ConditionNode(const std::string& name, const NodeConfig& config);
  void halt() override;
  NodeType type() const override final;
};
class SimpleConditionNode : public ConditionNode {
public:
  using TickFunctor = std::function<NodeStatus(TreeNode&)>;
  SimpleConditionNode(const std::string& name, TickFunctor tick_functor,
                      const NodeConfig& config);
protected:
  NodeStatus tick() override;
};
class DecoratorNode : public TreeNode {
public:
  DecoratorNode(const std::string& name, const NodeConfig& config);
  void setChild(TreeNode* child);
  const TreeNode* child() const;
  TreeNode* child();
  void halt() override;
  void haltChild();
  void resetChild();
  NodeType type() const override;
  NodeStatus executeTick() override;
protected:
  TreeNode* child_node_;
};
class ControlNode : public TreeNode {
public:
  ControlNode(const std::string& name, const NodeConfig& config);
  virtual void addChild(TreeNode* child);
  size_t childrenCount() const;
  const std::vector<TreeNode*>& children() const;
  const TreeNode* child(size_t index) const;
  void halt() override;
  void haltChild(size_t i);
  void haltChildren();
  void resetChildren();
  NodeType type() const override final;
protected:
  std::vector<TreeNode*> children_nodes_;
};

// a tree made by the factory: its subtrees, each with its blackboard
class Tree {
public:
  struct Subtree {
    using Ptr = std::shared_ptr<Subtree>;
    std::vector<TreeNode::Ptr> nodes;
    Blackboard::Ptr blackboard;
    std::string instance_name;
    std::string tree_ID;
  };
  std::vector<Subtree::Ptr> subtrees;
  Tree();
  Tree(Tree&& other);
  Tree& operator=(Tree&& other);
  void initialize();
  void haltTree();
  TreeNode* rootNode() const;
  NodeStatus tickOnce();
  NodeStatus tickExactlyOnce();
  NodeStatus tickWhileRunning(std::chrono::milliseconds sleep_time = std::chrono::milliseconds(10));
  NodeStatus tickRoot();  // version 3
  Blackboard::Ptr rootBlackboard();
  template<class D> void sleep(D timeout);
  void emitWakeUpSignal();
  uint16_t getUID();
  template<class F> void applyVisitor(F visitor);
};
template<class F> void applyRecursiveVisitor(TreeNode* root, const F& visitor);
void haltAllActions(TreeNode* root);

using NodeBuilder =
    std::function<std::unique_ptr<TreeNode>(const std::string&, const NodeConfig&)>;
class BehaviorTreeFactory {
public:
  BehaviorTreeFactory();
  ~BehaviorTreeFactory();
  void registerFromPlugin(const std::string& file_path);
  void registerFromROSPlugins();
  void registerBehaviorTreeFromFile(const std::filesystem::path& filename);
  void registerBehaviorTreeFromText(const std::string& xml_text);
  std::vector<std::string> registeredBehaviorTrees() const;
  void clearRegisteredBehaviorTrees();
  template<typename T, typename... Args> void registerNodeType(const std::string& ID, Args... args);
  template<typename T, typename... Args>
  void registerNodeType(const std::string& ID, const PortsList& ports, Args... args);
  void registerBuilder(const TreeNodeManifest& manifest, const NodeBuilder& builder);
  template<typename T> void registerBuilder(const std::string& ID, const NodeBuilder& builder);
  void registerSimpleAction(const std::string& ID,
                            const SimpleActionNode::TickFunctor& tick_functor,
                            PortsList ports = {});
  void registerSimpleCondition(const std::string& ID,
                               const SimpleConditionNode::TickFunctor& tick_functor,
                               PortsList ports = {});
  bool unregisterBuilder(const std::string& ID);
  const std::unordered_map<std::string, NodeBuilder>& builders() const;
  const std::unordered_map<std::string, TreeNodeManifest>& manifests() const;
  Tree createTreeFromText(const std::string& text,
                          Blackboard::Ptr blackboard = Blackboard::create());
  Tree createTreeFromFile(const std::string& file_path,
                          Blackboard::Ptr blackboard = Blackboard::create());
  Tree createTree(const std::string& tree_name,
                  Blackboard::Ptr blackboard = Blackboard::create());
  template<class R> void addSubstitutionRule(StringView filter, R rule);
  void loadSubstitutionRuleFromJSON(const std::string& json_text);
  void clearSubstitutionRules();
};
// the function a plugin library defines to register its nodes (BT_REGISTER_NODES)
#define BT_REGISTER_NODES(factory) \
  extern "C" void BT_RegisterNodesFromPlugin(BT::BehaviorTreeFactory& factory)
#define BTCPP_EXPORT

// the tree as the Groot editor's XML
std::string writeTreeNodesModelXML(const BehaviorTreeFactory& factory,
                                   bool include_builtin = false);
std::string WriteTreeToXML(const Tree& tree, bool add_metadata, bool add_builtin_models);

// loggers: told of every status change of a tree's nodes
class StatusChangeLogger {
public:
  StatusChangeLogger();
  explicit StatusChangeLogger(TreeNode* root_node);
  virtual ~StatusChangeLogger();
  virtual void callback(Duration timestamp, const TreeNode& node, NodeStatus prev_status,
                        NodeStatus status) = 0;
  virtual void flush() = 0;
  void setEnabled(bool enabled);
  bool enabled() const;
  bool showsTransitionToIdle() const;
  void enableTransitionToIdle(bool enable);
protected:
  void subscribeToTreeChanges(TreeNode* root_node);
};
class StdCoutLogger : public StatusChangeLogger {
public:
  explicit StdCoutLogger(const Tree& tree);
  void callback(Duration timestamp, const TreeNode& node, NodeStatus prev_status,
                NodeStatus status) override;
  void flush() override;
};
class FileLogger2 : public StatusChangeLogger {
public:
  FileLogger2(const Tree& tree, std::string filepath);
  void callback(Duration timestamp, const TreeNode& node, NodeStatus prev_status,
                NodeStatus status) override;
  void flush() override;
};
// serves a tree's state to the Groot2 editor over a socket (not ROS)
class Groot2Publisher : public StatusChangeLogger {
public:
  Groot2Publisher(const Tree& tree, unsigned server_port = 1667);
  void callback(Duration timestamp, const TreeNode& node, NodeStatus prev_status,
                NodeStatus status) override;
  void flush() override;
  void setMaxHeartbeatDelay(std::chrono::milliseconds delay);
};

class SharedLibrary {
public:
  SharedLibrary();
  SharedLibrary(const std::string& path, int flags = 0);
  void load(const std::string& path, int flags = 0);
  void unload();
  bool isLoaded() const;
  bool hasSymbol(const std::string& name);
  void* getSymbol(const std::string& name);
  const std::string& getPath() const;
  static std::string prefix();
  static std::string suffix();
  static std::string getOSName(const std::string& name);
};
}  // namespace BT
#endif
