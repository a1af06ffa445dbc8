// haros_arch stand-in for yaml-cpp (declarations only): the Node API ROS nodes use to read
// YAML (parameters, calibration, waypoints), the emitter, the exceptions and ``convert``.
// Every other yaml-cpp header stands in as this one (headers.UMBRELLAS).
#ifndef HAROS_STANDIN_YAML_CPP
#define HAROS_STANDIN_YAML_CPP
#include <cstddef>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
namespace YAML {
struct Mark {
  int pos;
  int line;
  int column;
  static const Mark null_mark();
  bool is_null() const;
};
struct NodeType {
  enum value { Undefined, Null, Scalar, Sequence, Map };
};
struct EmitterStyle {
  enum value { Default, Block, Flow };
};
class Node;
namespace detail {
struct iterator_value;
}
class iterator {
public:
  detail::iterator_value& operator*() const;
  detail::iterator_value* operator->() const;
  iterator& operator++();
  iterator operator++(int);
  bool operator==(const iterator& rhs) const;
  bool operator!=(const iterator& rhs) const;
};
typedef iterator const_iterator;
class Node {
public:
  Node();
  Node(const Node& rhs);
  explicit Node(NodeType::value type);
  template<class T> explicit Node(const T& rhs);
  ~Node();
  NodeType::value Type() const;
  bool IsDefined() const;
  bool IsNull() const;
  bool IsScalar() const;
  bool IsSequence() const;
  bool IsMap() const;
  explicit operator bool() const;
  bool operator!() const;
  template<class T> T as() const;
  template<class T, class S> T as(const S& fallback) const;
  const std::string& Scalar() const;
  const std::string& Tag() const;
  void SetTag(const std::string& tag);
  EmitterStyle::value Style() const;
  void SetStyle(EmitterStyle::value style);
  YAML::Mark Mark() const;
  bool is(const Node& rhs) const;
  template<class T> Node& operator=(const T& rhs);
  Node& operator=(const Node& rhs);
  void reset(const Node& rhs = Node());
  std::size_t size() const;
  const_iterator begin() const;
  iterator begin();
  const_iterator end() const;
  iterator end();
  template<class T> void push_back(const T& rhs);
  void push_back(const Node& rhs);
  template<class Key> const Node operator[](const Key& key) const;
  template<class Key> Node operator[](const Key& key);
  template<class Key> bool remove(const Key& key);
  const Node operator[](const Node& key) const;
  Node operator[](const Node& key);
  bool remove(const Node& key);
  template<class Key, class Value> void force_insert(const Key& key, const Value& value);
  // yaml-cpp 0.3 (ROS 1 code keeps it in the #else of HAVE_YAMLCPP_GT_0_5_0)
  template<class Key> const Node* FindValue(const Key& key) const;
  template<class T> bool Read(T& value) const;
  template<class T> const T to() const;
};
namespace detail {
struct iterator_value : public Node, public std::pair<Node, Node> {
  iterator_value();
};
}
bool operator==(const Node& lhs, const Node& rhs);
Node Clone(const Node& node);
template<class T> struct convert;
template<class T> struct as_if;
Node Load(const std::string& input);
Node Load(const char* input);
Node Load(std::istream& input);
Node LoadFile(const std::string& filename);
std::vector<Node> LoadAll(const std::string& input);
std::vector<Node> LoadAll(const char* input);
std::vector<Node> LoadAll(std::istream& input);
std::vector<Node> LoadAllFromFile(const std::string& filename);
std::string Dump(const Node& node);
// yaml-cpp 0.3: ``doc["resolution"] >> res;``, ``Parser(stream).GetNextDocument(doc)``
// (overloads, not a template: code that defines its own template ``operator>>`` for
// yaml-cpp 0.5, map_server's, still has one best match)
void operator>>(const Node& node, bool& value);
void operator>>(const Node& node, char& value);
void operator>>(const Node& node, int& value);
void operator>>(const Node& node, unsigned int& value);
void operator>>(const Node& node, long& value);
void operator>>(const Node& node, unsigned long& value);
void operator>>(const Node& node, long long& value);
void operator>>(const Node& node, unsigned long long& value);
void operator>>(const Node& node, float& value);
void operator>>(const Node& node, double& value);
void operator>>(const Node& node, std::string& value);
class Parser {
public:
  Parser();
  explicit Parser(std::istream& in);
  explicit operator bool() const;
  void Load(std::istream& in);
  bool GetNextDocument(Node& document);
};
std::ostream& operator<<(std::ostream& out, const Node& node);
enum EMITTER_MANIP {
  Auto, TagByKind, Newline, EmitNonAscii, EscapeNonAscii, EscapeAsJson, SingleQuoted,
  DoubleQuoted, Literal, YesNoBool, TrueFalseBool, OnOffBool, UpperCase, LowerCase,
  CamelCase, LongBool, ShortBool, Dec, Hex, Oct, BeginDoc, EndDoc, BeginSeq, EndSeq, Flow,
  Block, BeginMap, EndMap, Key, Value, LongKey
};
class Emitter {
public:
  Emitter();
  explicit Emitter(std::ostream& stream);
  ~Emitter();
  const char* c_str() const;
  std::size_t size() const;
  bool good() const;
  const std::string GetLastError() const;
  bool SetIndent(std::size_t n);
  bool SetPreCommentIndent(std::size_t n);
  bool SetPostCommentIndent(std::size_t n);
  bool SetFloatPrecision(std::size_t n);
  bool SetDoublePrecision(std::size_t n);
  bool SetMapFormat(EMITTER_MANIP value);
  bool SetSeqFormat(EMITTER_MANIP value);
  Emitter& SetLocalValue(EMITTER_MANIP value);
  Emitter& Write(const std::string& str);
  Emitter& Write(bool b);
  Emitter& Write(const Node& node);
  template<class T> Emitter& WriteIntegralType(T value);
  template<class T> Emitter& WriteStreamable(T value);
};
template<class T> Emitter& operator<<(Emitter& out, const T& value);
struct _Comment {
  std::string content;
};
_Comment Comment(const std::string& content);
class Exception : public std::runtime_error {
public:
  Exception(const YAML::Mark& mark, const std::string& msg);
  YAML::Mark mark;
  std::string msg;
};
class ParserException : public Exception {
public:
  ParserException(const YAML::Mark& mark, const std::string& msg);
};
class RepresentationException : public Exception {
public:
  RepresentationException(const YAML::Mark& mark, const std::string& msg);
};
class InvalidScalar : public RepresentationException {
public:
  explicit InvalidScalar(const YAML::Mark& mark);
};
class KeyNotFound : public RepresentationException {
public:
  template<class T> KeyNotFound(const YAML::Mark& mark, const T& key);
};
class InvalidNode : public RepresentationException {
public:
  explicit InvalidNode(const std::string& key);
};
class BadConversion : public RepresentationException {
public:
  explicit BadConversion(const YAML::Mark& mark);
};
class BadDereference : public RepresentationException {
public:
  BadDereference();
};
class BadSubscript : public RepresentationException {
public:
  template<class Key> BadSubscript(const YAML::Mark& mark, const Key& key);
};
class BadPushback : public RepresentationException {
public:
  BadPushback();
};
class BadInsert : public RepresentationException {
public:
  BadInsert();
};
class EmitterException : public Exception {
public:
  explicit EmitterException(const std::string& msg);
};
class BadFile : public Exception {
public:
  explicit BadFile(const std::string& filename);
};
}  // namespace YAML
#endif
