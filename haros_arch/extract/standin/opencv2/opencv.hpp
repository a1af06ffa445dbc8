// haros_arch stand-in: the OpenCV basics ROS image nodes use (declarations only). Every
// OpenCV header (<opencv2/core/core.hpp>, <opencv2/highgui.hpp>, ...) includes this file.
#ifndef HAROS_STANDIN_OPENCV_HPP
#define HAROS_STANDIN_OPENCV_HPP
#include <string>
#include <vector>
// opencv2/core/version.hpp: the OpenCV 4 of noetic's and jazzy's platforms (code picks
// its OpenCV 3+ API by CV_MAJOR_VERSION)
#define CV_VERSION_MAJOR 4
#define CV_VERSION_MINOR 5
#define CV_VERSION_REVISION 4
#define CV_VERSION "4.5.4"
#define CV_MAJOR_VERSION CV_VERSION_MAJOR
#define CV_MINOR_VERSION CV_VERSION_MINOR
#define CV_SUBMINOR_VERSION CV_VERSION_REVISION
#define CV_8U 0
#define CV_8S 1
#define CV_16U 2
#define CV_16S 3
#define CV_32S 4
#define CV_32F 5
#define CV_64F 6
#define CV_8UC1 0
#define CV_8UC3 16
#define CV_8UC4 24
#define CV_16UC1 2
#define CV_8UC2 8
#define CV_16SC1 3
#define CV_16UC3 18
#define CV_32SC1 4
#define CV_32FC1 5
#define CV_32FC3 21
#define CV_64FC1 6
#define CV_PI 3.1415926535897932384626433832795
#define CV_AA 16
#define CV_RGB(r, g, b) cv::Scalar((b), (g), (r))
#define CV_BGR2GRAY 6
#define CV_RGB2GRAY 7
#define CV_GRAY2BGR 8
#define CV_BGR2RGB 4
#define CV_WINDOW_AUTOSIZE 1
typedef unsigned char uchar;  // global in OpenCV (cvdef.h)
typedef unsigned short ushort;
namespace cv {
using ::uchar;
// OpenCV 2.x's ``using std::vector;`` (core/core.hpp): ``cv::vector<cv::Mat>`` of
// kinetic-era nodes is std's, and beside ``using namespace cv; using namespace std;``
// a bare ``vector`` is not ambiguous (IGVC2015's sb_vision); the same entity for 3 and 4
using std::vector;
template<class T> class Rect_;
template<class T> class Point_ {
public:
  Point_(); Point_(T x, T y);
  template<class U> operator Point_<U>() const;
  T dot(const Point_& p) const;
  double ddot(const Point_& p) const;
  double cross(const Point_& p) const;
  bool inside(const Rect_<T>& r) const;
  T x, y;
};
template<class T> Point_<T> operator+(const Point_<T>& a, const Point_<T>& b);
template<class T> Point_<T> operator-(const Point_<T>& a, const Point_<T>& b);
template<class T> Point_<T> operator-(const Point_<T>& a);
template<class T> Point_<T> operator*(const Point_<T>& a, double s);
template<class T> Point_<T> operator*(double s, const Point_<T>& a);
template<class T> Point_<T> operator/(const Point_<T>& a, double s);
template<class T> Point_<T>& operator+=(Point_<T>& a, const Point_<T>& b);
template<class T> Point_<T>& operator-=(Point_<T>& a, const Point_<T>& b);
template<class T> Point_<T>& operator*=(Point_<T>& a, double s);
template<class T> Point_<T>& operator/=(Point_<T>& a, double s);
template<class T> bool operator==(const Point_<T>& a, const Point_<T>& b);
template<class T> bool operator!=(const Point_<T>& a, const Point_<T>& b);
template<class T> double norm(const Point_<T>& p);
typedef Point_<int> Point;
typedef Point_<int> Point2i;
typedef Point_<float> Point2f;
typedef Point_<double> Point2d;
template<class T> class Point3_ {
public:
  Point3_(); Point3_(T x, T y, T z);
  template<class U> operator Point3_<U>() const;
  T dot(const Point3_& p) const;
  Point3_ cross(const Point3_& p) const;
  T x, y, z;
};
template<class T> Point3_<T> operator+(const Point3_<T>& a, const Point3_<T>& b);
template<class T> Point3_<T> operator-(const Point3_<T>& a, const Point3_<T>& b);
template<class T> Point3_<T> operator-(const Point3_<T>& a);
template<class T> Point3_<T> operator*(const Point3_<T>& a, double s);
template<class T> Point3_<T> operator*(double s, const Point3_<T>& a);
template<class T> Point3_<T> operator/(const Point3_<T>& a, double s);
template<class T> Point3_<T>& operator+=(Point3_<T>& a, const Point3_<T>& b);
template<class T> Point3_<T>& operator-=(Point3_<T>& a, const Point3_<T>& b);
template<class T> double norm(const Point3_<T>& p);
typedef Point3_<float> Point3f;
typedef Point3_<double> Point3d;
template<class T> class Size_ {
public:
  Size_(); Size_(T w, T h);
  template<class U> operator Size_<U>() const;
  T width, height;
  T area() const;
  bool empty() const;
};
template<class T> Size_<T> operator*(const Size_<T>& a, T s);
template<class T> Size_<T> operator/(const Size_<T>& a, T s);
template<class T> Size_<T> operator+(const Size_<T>& a, const Size_<T>& b);
template<class T> Size_<T> operator-(const Size_<T>& a, const Size_<T>& b);
template<class T> bool operator==(const Size_<T>& a, const Size_<T>& b);
template<class T> bool operator!=(const Size_<T>& a, const Size_<T>& b);
typedef Size_<int> Size;
typedef Size_<float> Size2f;
template<class T> class Rect_ {
public:
  Rect_(); Rect_(T x, T y, T w, T h);
  Rect_(const Point_<T>& a, const Point_<T>& b);
  Rect_(const Point_<T>& origin, const Size_<T>& size);
  T x, y, width, height;
  T area() const;
  Point_<T> tl() const;
  Point_<T> br() const;
  Size_<T> size() const;
  bool empty() const;
  bool contains(const Point_<T>& p) const;
};
template<class T> Rect_<T> operator&(const Rect_<T>& a, const Rect_<T>& b);
template<class T> Rect_<T> operator|(const Rect_<T>& a, const Rect_<T>& b);
typedef Rect_<int> Rect;
class Scalar {
public:
  Scalar(); Scalar(double v0, double v1 = 0, double v2 = 0, double v3 = 0);
  static Scalar all(double v);
  double operator[](int i) const;
  double& operator[](int i);
  bool operator==(const Scalar& other) const;
  bool operator!=(const Scalar& other) const;
  double val[4];
};
template<class T, int n> class Vec;
// a small fixed-size matrix (core/matx.hpp): any number of initial values
template<class T, int m, int n> class Matx {
public:
  Matx();
  template<class... A> Matx(T v0, A... more);
  explicit Matx(const T* values);
  T& operator()(int i, int j); const T& operator()(int i, int j) const;
  T& operator()(int i); const T& operator()(int i) const;
  Matx<T, n, m> t() const;
  Matx inv(int method = 0) const;
  Matx operator-() const;
  T dot(const Matx& other) const;
  static Matx eye(); static Matx zeros(); static Matx ones(); static Matx all(T value);
  T val[m * n];
};
template<class T, int m, int k, int n> Matx<T, m, n> operator*(const Matx<T, m, k>& a, const Matx<T, k, n>& b);
template<class T, int m, int n> Vec<T, m> operator*(const Matx<T, m, n>& a, const Vec<T, n>& b);
template<class T, int m, int n> Matx<T, m, n> operator*(const Matx<T, m, n>& a, double s);
template<class T, int m, int n> Matx<T, m, n> operator+(const Matx<T, m, n>& a, const Matx<T, m, n>& b);
template<class T, int m, int n> Matx<T, m, n> operator-(const Matx<T, m, n>& a, const Matx<T, m, n>& b);
// a vector is a one-column Matx (core/matx.hpp): ``t()``, products, ``val``
template<class T, int n> class Vec : public Matx<T, n, 1> {
public:
  Vec();
  template<class... A> Vec(T v0, A... more);
  Vec(const Matx<T, n, 1>& m);
  T& operator[](int i); const T& operator[](int i) const;
  T& operator()(int i); const T& operator()(int i) const;
  Vec operator-() const;
  Vec cross(const Vec& v) const;  // of three elements (core/matx.inl.hpp)
  Vec mul(const Vec& v) const;
};
// a vector's own arithmetic (core/matx.hpp): in place, by a scalar, of two vectors
template<class T, int n> Vec<T, n>& operator+=(Vec<T, n>& a, const Vec<T, n>& b);
template<class T, int n> Vec<T, n>& operator-=(Vec<T, n>& a, const Vec<T, n>& b);
template<class T, int n> Vec<T, n>& operator*=(Vec<T, n>& a, double s);
template<class T, int n> Vec<T, n>& operator/=(Vec<T, n>& a, double s);
template<class T, int n> Vec<T, n> operator+(const Vec<T, n>& a, const Vec<T, n>& b);
template<class T, int n> Vec<T, n> operator-(const Vec<T, n>& a, const Vec<T, n>& b);
template<class T, int n> Vec<T, n> operator*(const Vec<T, n>& a, double s);
template<class T, int n> Vec<T, n> operator*(double s, const Vec<T, n>& a);
template<class T, int n> Vec<T, n> operator/(const Vec<T, n>& a, double s);
template<class T, int m, int n> Matx<T, m, n>& operator+=(Matx<T, m, n>& a, const Matx<T, m, n>& b);
template<class T, int m, int n> Matx<T, m, n>& operator-=(Matx<T, m, n>& a, const Matx<T, m, n>& b);
template<class T, int m, int n> Matx<T, m, n>& operator*=(Matx<T, m, n>& a, double s);
template<class T, int m, int n> Matx<T, m, n> operator/(const Matx<T, m, n>& a, double s);
typedef Vec<uchar, 3> Vec3b;
typedef Vec<uchar, 4> Vec4b;
typedef Vec<int, 2> Vec2i;
typedef Vec<int, 3> Vec3i;
typedef Vec<int, 4> Vec4i;
typedef Vec<float, 2> Vec2f;
typedef Vec<float, 3> Vec3f;
typedef Vec<float, 4> Vec4f;
typedef Vec<float, 6> Vec6f;
typedef Vec<double, 2> Vec2d;
typedef Vec<double, 3> Vec3d;
typedef Vec<double, 4> Vec4d;
typedef Matx<float, 2, 2> Matx22f;
typedef Matx<double, 2, 2> Matx22d;
typedef Matx<float, 3, 3> Matx33f;
typedef Matx<double, 3, 3> Matx33d;
typedef Matx<float, 3, 4> Matx34f;
typedef Matx<double, 3, 4> Matx34d;
typedef Matx<float, 4, 4> Matx44f;
typedef Matx<double, 4, 4> Matx44d;
typedef Matx<float, 3, 1> Matx31f;
typedef Matx<double, 3, 1> Matx31d;
typedef Matx<float, 1, 3> Matx13f;
typedef Matx<double, 1, 3> Matx13d;
class Range { public: Range(); Range(int start, int end); static Range all(); int start, end; int size() const; };
class Mat {
public:
  Mat();
  Mat(int rows, int cols, int type);
  Mat(int rows, int cols, int type, const Scalar& value);
  Mat(int rows, int cols, int type, void* data, size_t step = 0);
  Mat(Size size, int type);
  Mat(Size size, int type, const Scalar& value);
  Mat(Size size, int type, void* data, size_t step = 0);  // (a message's pixels, not copied)
  Mat(const Mat& m, const Rect& roi);
  Mat(const Mat& m, const Range& rows, const Range& cols = Range::all());
  Mat(const Mat& m);
  template<class T> explicit Mat(const std::vector<T>& values, bool copy = false);
  template<class T, int m, int n> Mat(const Matx<T, m, n>& values, bool copy = true);
  template<class T, int n> Mat(const Vec<T, n>& values, bool copy = true);
  template<class T> explicit Mat(const Point_<T>& p, bool copy = true);
  template<class T> explicit Mat(const Point3_<T>& p, bool copy = true);
  Mat& operator=(const Mat& m);
  Mat& operator=(const Scalar& s);
  Mat operator()(const Rect& roi) const;
  // a region of known size read as a small matrix (msckf_vio's ``cv::Matx33d
  // R(T(cv::Rect(0, 0, 3, 3)))``, ``cv::Vec3d t = T(cv::Rect(3, 0, 1, 3))``)
  template<class T, int m, int n> operator Matx<T, m, n>() const;
  template<class T, int n> operator Vec<T, n>() const;
  Mat operator()(const Range& rows, const Range& cols) const;
  Mat rowRange(int start, int end) const;
  Mat rowRange(const Range& r) const;
  Mat colRange(int start, int end) const;
  Mat colRange(const Range& r) const;
  Mat diag(int d = 0) const;
  Mat mul(const Mat& m, double scale = 1) const;
  Mat cross(const Mat& m) const;
  Mat& setTo(const Scalar& value);
  Mat& setTo(const Scalar& value, const Mat& mask);
  // any array value (``img.setTo(cv::Vec3b(0, 0, 255), mask)``: OpenCV's InputArray)
  template<class V> Mat& setTo(const V& value, const Mat& mask);
  void push_back(const Mat& m);
  int checkVector(int channels, int depth = -1, bool continuous = true) const;
  Mat getMat(int index = -1) const;  // InputArray's, which is a Mat here
  void copyTo(std::vector<Mat>& out) const;
  Mat clone() const;
  void copyTo(Mat& m) const;
  void copyTo(Mat& m, const Mat& mask) const;
  void copyTo(Mat&& m) const;  // a region of another matrix
  void copyTo(Mat&& m, const Mat& mask) const;
  void convertTo(Mat& m, int rtype, double alpha = 1, double beta = 0) const;
  Mat reshape(int cn, int rows = 0) const;
  Mat row(int y) const;
  Mat col(int x) const;
  Mat t() const;
  Mat inv() const;
  double dot(const Mat& m) const;
  void create(int rows, int cols, int type);
  void release();
  bool empty() const;
  bool isContinuous() const;
  size_t total() const;
  int type() const;
  int depth() const;
  int channels() const;
  size_t elemSize() const;
  // ``m.size()`` and, of a matrix of several dimensions, ``m.size[2]``: OpenCV's MatSize
  // member (kachaka's hand recognition reads a network's output so)
  struct MatSize {
    Size operator()() const;
    const int& operator[](int i) const;
    int& operator[](int i);
    int dims() const;
  } size;
  template<class T> T& at(int row, int col);
  template<class T> const T& at(int row, int col) const;
  template<class T> T& at(int i);
  template<class T> T& at(Point pt);
  template<class T> T* ptr(int row = 0);
  uchar* ptr(int row = 0);
  template<class T> T* ptr(int i0, int i1);
  uchar* ptr(int i0, int i1);
  static Mat zeros(int rows, int cols, int type);
  static Mat zeros(Size size, int type);
  static Mat ones(int rows, int cols, int type);
  static Mat ones(Size size, int type);
  static Mat eye(int rows, int cols, int type);
  int rows, cols, dims, flags;
  uchar* data;
  const uchar* datastart;
  const uchar* dataend;
  size_t step;
};
typedef Mat InputArray;
typedef Mat OutputArray;
typedef Mat InputOutputArray;
template<class T> class Mat_ : public Mat {
public:
  Mat_(); Mat_(int rows, int cols); Mat_(int rows, int cols, const T& value);
  Mat_(int rows, int cols, T* data, size_t step = 0);  // a view of data the caller keeps
  Mat_(const Mat& m);
  template<int m, int n> Mat_(const Matx<T, m, n>& values, bool copy = true);
  T& operator()(int r, int c); const T& operator()(int r, int c) const;
  T& operator()(int i); const T& operator()(int i) const;
  T& operator()(Point pt); const T& operator()(Point pt) const;
  Mat_ t() const; Mat_ inv(int method = 0) const;
};
typedef Mat_<double> Mat1d;
typedef Mat_<float> Mat1f;
typedef Mat_<uchar> Mat1b;
typedef Mat_<int> Mat1i;
// `(Mat_<double>(3, 3) << 1, 0, 0, ...)`
template<class T> class MatCommaInitializer_ {
public:
  template<class V> MatCommaInitializer_& operator,(V value);
  operator Mat_<T>() const;
  Mat_<T> operator*() const;
};
template<class T, class V> MatCommaInitializer_<T> operator<<(const Mat_<T>& m, V value);
Mat operator+(const Mat& a, const Mat& b);
Mat operator+(const Mat& a, const Scalar& s);
Mat operator-(const Mat& a, const Mat& b);
Mat operator-(const Mat& a, const Scalar& s);
Mat operator-(const Mat& a);
Mat operator*(const Mat& a, const Mat& b);
Mat operator*(const Mat& a, double s);
Mat operator*(double s, const Mat& a);
Mat operator/(const Mat& a, double s);
Mat operator/(const Mat& a, const Mat& b);
Mat& operator+=(Mat& a, const Mat& b);
Mat& operator-=(Mat& a, const Mat& b);
Mat& operator*=(Mat& a, double s);
Mat& operator/=(Mat& a, double s);
Mat operator>(const Mat& a, double s);
Mat operator<(const Mat& a, double s);
Mat operator==(const Mat& a, double s);
Mat operator&(const Mat& a, const Mat& b);
Mat operator|(const Mat& a, const Mat& b);
Mat operator~(const Mat& a);
double norm(const Mat& src, int type = 4);
double norm(const Mat& a, const Mat& b, int type = 4);
double determinant(const Mat& m);
double invert(const Mat& src, Mat& dst, int flags = 0);
bool solve(const Mat& a, const Mat& b, Mat& dst, int flags = 0);
void transpose(const Mat& src, Mat& dst);
void hconcat(const Mat& a, const Mat& b, Mat& dst);
void vconcat(const Mat& a, const Mat& b, Mat& dst);
void Rodrigues(const Mat& src, Mat& dst);
void Rodrigues(const Mat& src, Mat& dst, Mat& jacobian);
Scalar mean(const Mat& src);
Scalar mean(const Mat& src, const Mat& mask);
int countNonZero(const Mat& src);
void minMaxIdx(const Mat& src, double* min, double* max = 0, int* min_idx = 0, int* max_idx = 0);
void absdiff(const Mat& a, const Mat& b, Mat& dst);
void add(const Mat& a, const Mat& b, Mat& dst);
void subtract(const Mat& a, const Mat& b, Mat& dst);
void multiply(const Mat& a, const Mat& b, Mat& dst, double scale = 1);
void addWeighted(const Mat& a, double alpha, const Mat& b, double beta, double gamma, Mat& dst);
void bitwise_and(const Mat& a, const Mat& b, Mat& dst);
void bitwise_or(const Mat& a, const Mat& b, Mat& dst);
void bitwise_not(const Mat& a, Mat& dst);
void equalizeHist(const Mat& src, Mat& dst);
void remap(const Mat& src, Mat& dst, const Mat& map1, const Mat& map2, int interpolation, int border = 0, const Scalar& value = Scalar());
void warpAffine(const Mat& src, Mat& dst, const Mat& m, Size size, int flags = 1);
void warpPerspective(const Mat& src, Mat& dst, const Mat& m, Size size, int flags = 1);
Mat getRotationMatrix2D(Point2f center, double angle, double scale);
void dilate(const Mat& src, Mat& dst, const Mat& kernel);
void erode(const Mat& src, Mat& dst, const Mat& kernel);
enum { MORPH_RECT = 0, MORPH_CROSS = 1, MORPH_ELLIPSE = 2 };
// imgproc.hpp's morphological operations
enum { MORPH_ERODE = 0, MORPH_DILATE = 1, MORPH_OPEN = 2, MORPH_CLOSE = 3,
       MORPH_GRADIENT = 4, MORPH_TOPHAT = 5, MORPH_BLACKHAT = 6 };
void morphologyEx(const Mat& src, Mat& dst, int op, const Mat& kernel,
                  Point anchor = Point(-1, -1), int iterations = 1, int border = 0,
                  const Scalar& value = Scalar());
Mat getStructuringElement(int shape, Size size, Point anchor = Point(-1, -1));
// core/eigen.hpp: between OpenCV and Eigen matrices
template<class M> void cv2eigen(const Mat& src, M& dst);
template<class M> void eigen2cv(const M& src, Mat& dst);
// core/persistence.hpp: reading and writing XML / YAML settings files
class FileNodeIterator;
class FileNode {
public:
  enum { NONE = 0, INT = 1, REAL = 2, FLOAT = 2, STR = 3, STRING = 3, SEQ = 4, MAP = 5,
         TYPE_MASK = 7, FLOW = 8, UNIFORM = 8, EMPTY = 16, NAMED = 32 };
  FileNode();
  FileNode operator[](const std::string& key) const;
  FileNode operator[](const char* key) const;
  FileNode operator[](int i) const;
  int type() const;
  bool empty() const; bool isNone() const; bool isSeq() const; bool isMap() const;
  bool isInt() const; bool isReal() const; bool isString() const; bool isNamed() const;
  std::string name() const;
  size_t size() const;
  operator int() const; operator float() const; operator double() const;
  operator std::string() const;
  double real() const; std::string string() const; Mat mat() const;
  FileNodeIterator begin() const; FileNodeIterator end() const;
};
class FileNodeIterator {
public:
  FileNode operator*() const;
  FileNodeIterator& operator++(); FileNodeIterator operator++(int);
  bool operator==(const FileNodeIterator& other) const;
  bool operator!=(const FileNodeIterator& other) const;
};
class FileStorage {
public:
  enum Mode { READ = 0, WRITE = 1, APPEND = 2, MEMORY = 4, FORMAT_AUTO = 0,
              FORMAT_XML = 8, FORMAT_YAML = 16, FORMAT_JSON = 24 };
  FileStorage();
  FileStorage(const std::string& filename, int flags, const std::string& encoding = std::string());
  bool open(const std::string& filename, int flags, const std::string& encoding = std::string());
  bool isOpened() const;
  void release();
  std::string releaseAndGetString();
  FileNode getFirstTopLevelNode() const;
  FileNode root(int index = 0) const;
  FileNode operator[](const std::string& name) const;
  FileNode operator[](const char* name) const;
  void write(const std::string& name, int value);
  void write(const std::string& name, double value);
  void write(const std::string& name, const std::string& value);
  void write(const std::string& name, const Mat& value);
  void writeComment(const std::string& comment, bool append = false);
  template<class T> FileStorage& operator<<(const T& value);
};
template<class T> void operator>>(const FileNode& node, T& value);
template<class T> void read(const FileNode& node, T& value, const T& fallback);
enum { COLOR_BGR2GRAY = 6, COLOR_RGB2GRAY = 7, COLOR_GRAY2BGR = 8, COLOR_BGR2RGB = 4,
       COLOR_RGB2BGR = 4, COLOR_BGR2HSV = 40, COLOR_HSV2BGR = 54, COLOR_BGRA2BGR = 1,
       COLOR_YUV2BGR_UYVY = 108, COLOR_YUV2BGR_YUYV = 116 };
enum CmpTypes { CMP_EQ = 0, CMP_GT = 1, CMP_GE = 2, CMP_LT = 3, CMP_LE = 4, CMP_NE = 5 };
enum { INTER_NEAREST = 0, INTER_LINEAR = 1, INTER_CUBIC = 2, INTER_AREA = 3 };
enum { THRESH_BINARY = 0, THRESH_BINARY_INV = 1, THRESH_OTSU = 8 };
enum { WINDOW_NORMAL = 0, WINDOW_AUTOSIZE = 1, WINDOW_OPENGL = 0x1000,
  WINDOW_FULLSCREEN = 1, WINDOW_FREERATIO = 0x100, WINDOW_KEEPRATIO = 0,
  WINDOW_GUI_EXPANDED = 0, WINDOW_GUI_NORMAL = 0x10 };
enum { WND_PROP_FULLSCREEN = 0, WND_PROP_AUTOSIZE = 1, WND_PROP_ASPECT_RATIO = 2,
  WND_PROP_OPENGL = 3, WND_PROP_VISIBLE = 4 };
enum { EVENT_MOUSEMOVE = 0, EVENT_LBUTTONDOWN = 1, EVENT_RBUTTONDOWN = 2,
  EVENT_MBUTTONDOWN = 3, EVENT_LBUTTONUP = 4, EVENT_RBUTTONUP = 5, EVENT_MBUTTONUP = 6,
  EVENT_LBUTTONDBLCLK = 7, EVENT_RBUTTONDBLCLK = 8, EVENT_MBUTTONDBLCLK = 9,
  EVENT_MOUSEWHEEL = 10, EVENT_MOUSEHWHEEL = 11 };
enum { EVENT_FLAG_LBUTTON = 1, EVENT_FLAG_RBUTTON = 2, EVENT_FLAG_MBUTTON = 4,
  EVENT_FLAG_CTRLKEY = 8, EVENT_FLAG_SHIFTKEY = 16, EVENT_FLAG_ALTKEY = 32 };
typedef void (*MouseCallback)(int event, int x, int y, int flags, void* userdata);
enum { LINE_4 = 4, LINE_8 = 8, LINE_AA = 16, FILLED = -1 };
enum { FONT_HERSHEY_SIMPLEX = 0, FONT_HERSHEY_PLAIN = 1 };
enum { RETR_EXTERNAL = 0, RETR_LIST = 1, RETR_CCOMP = 2, RETR_TREE = 3, CHAIN_APPROX_NONE = 1,
       CHAIN_APPROX_SIMPLE = 2, CHAIN_APPROX_TC89_L1 = 3, CHAIN_APPROX_TC89_KCOS = 4 };
enum { CAP_PROP_FRAME_WIDTH = 3, CAP_PROP_FRAME_HEIGHT = 4, CAP_PROP_FPS = 5 };
enum ImreadModes { IMREAD_COLOR = 1, IMREAD_GRAYSCALE = 0, IMREAD_UNCHANGED = -1 };
Mat imdecode(const std::vector<uchar>& buf, int flags);
int floodFill(Mat& image, Point seed, const Scalar& value);
void compare(const Mat& a, double b, Mat& dst, int cmpop);
void compare(const Mat& a, const Mat& b, Mat& dst, int cmpop);
void cvtColor(const Mat& src, Mat& dst, int code, int dst_cn = 0);
void resize(const Mat& src, Mat& dst, Size size, double fx = 0, double fy = 0, int interpolation = 1);
void GaussianBlur(const Mat& src, Mat& dst, Size ksize, double sx, double sy = 0, int border = 4);
void blur(const Mat& src, Mat& dst, Size ksize);
void medianBlur(const Mat& src, Mat& dst, int ksize);
double threshold(const Mat& src, Mat& dst, double thresh, double maxval, int type);
void Canny(const Mat& src, Mat& edges, double t1, double t2, int aperture = 3, bool l2 = false);
void flip(const Mat& src, Mat& dst, int code);
void split(const Mat& src, std::vector<Mat>& channels);
void merge(const std::vector<Mat>& channels, Mat& dst);
void inRange(const Mat& src, const Scalar& lower, const Scalar& upper, Mat& dst);
void findContours(Mat& image, std::vector<std::vector<Point> >& contours, int mode, int method,
                  Point offset = Point());
// with the contours' hierarchy (next, previous, first child, parent of each)
void findContours(Mat& image, std::vector<std::vector<Point> >& contours,
                  std::vector<Vec4i>& hierarchy, int mode, int method, Point offset = Point());
void drawContours(Mat& image, const std::vector<std::vector<Point> >& contours, int index, const Scalar& color, int thickness = 1, int line = 8);
void drawContours(Mat& image, const std::vector<std::vector<Point> >& contours, int index,
                  const Scalar& color, int thickness, int line,
                  const std::vector<Vec4i>& hierarchy, int max_level = 2147483647,
                  Point offset = Point());
double contourArea(const std::vector<Point>& contour, bool oriented = false);
double contourArea(const std::vector<Point2f>& contour, bool oriented = false);
// a shape's spatial, central and normalised central moments
class Moments {
public:
  Moments();
  double m00, m10, m01, m20, m11, m02, m30, m21, m12, m03;
  double mu20, mu11, mu02, mu30, mu21, mu12, mu03;
  double nu20, nu11, nu02, nu30, nu21, nu12, nu03;
};
Moments moments(const std::vector<Point>& contour, bool binary_image = false);
Moments moments(const std::vector<Point2f>& contour, bool binary_image = false);
Moments moments(const Mat& image, bool binary_image = false);
void circle(Mat& img, Point center, int radius, const Scalar& color, int thickness = 1, int line = 8, int shift = 0);
void line(Mat& img, Point a, Point b, const Scalar& color, int thickness = 1, int line = 8, int shift = 0);
void rectangle(Mat& img, Point a, Point b, const Scalar& color, int thickness = 1, int line = 8, int shift = 0);
void rectangle(Mat& img, Rect rect, const Scalar& color, int thickness = 1, int line = 8, int shift = 0);
void putText(Mat& img, const std::string& text, Point org, int font, double scale, Scalar color, int thickness = 1, int line = 8, bool bottom_left = false);
void normalize(const Mat& src, Mat& dst, double alpha = 1, double beta = 0, int norm = 4, int dtype = -1);
void minMaxLoc(const Mat& src, double* min, double* max = 0, Point* min_loc = 0, Point* max_loc = 0);
void undistort(const Mat& src, Mat& dst, const Mat& camera, const Mat& distortion);
Mat imread(const std::string& path, int flags = 1);
bool imwrite(const std::string& path, const Mat& img);
void imshow(const std::string& window, const Mat& img);
void namedWindow(const std::string& window, int flags = 1);
void destroyWindow(const std::string& window);
void destroyAllWindows();
int waitKey(int delay = 0);
void startWindowThread();
void setMouseCallback(const std::string& window, MouseCallback on_mouse, void* userdata = 0);
void resizeWindow(const std::string& window, int width, int height);
void moveWindow(const std::string& window, int x, int y);
void setWindowTitle(const std::string& window, const std::string& title);
double getWindowProperty(const std::string& window, int prop);
void setWindowProperty(const std::string& window, int prop, double value);
// the capture back ends a caller may ask for (videoio.hpp's VideoCaptureAPIs)
enum VideoCaptureAPIs { CAP_ANY = 0, CAP_V4L = 200, CAP_V4L2 = 200, CAP_FIREWIRE = 300,
                        CAP_DSHOW = 700, CAP_OPENNI = 900, CAP_GSTREAMER = 1800,
                        CAP_FFMPEG = 1900, CAP_IMAGES = 2000 };
class VideoCapture {
public:
  VideoCapture();
  explicit VideoCapture(int device, int api_preference = CAP_ANY);
  explicit VideoCapture(const std::string& path, int api_preference = CAP_ANY);
  bool open(int device, int api_preference = CAP_ANY);
  bool open(const std::string& path, int api_preference = CAP_ANY);
  bool isOpened() const;
  bool read(Mat& image);
  bool grab();
  bool retrieve(Mat& image, int channel = 0);
  VideoCapture& operator>>(Mat& image);
  bool set(int prop, double value);
  double get(int prop) const;
  void release();
};
class VideoWriter { public: VideoWriter(); bool isOpened() const; void write(const Mat& image); };
}  // namespace cv
// highgui's C API (opencv2/highgui/highgui_c.h): the native handle of a window (image_view
// gives it to GTK) and the window thread
extern "C" {
void* cvGetWindowHandle(const char* name);
int cvStartWindowThread();
}
#endif
