// haros_arch stand-in: the Qt basics ROS nodes with a GUI use (declarations only).
// Every Qt header (<QObject>, <QtWidgets/QWidget>, ...) includes this one file.
#ifndef HAROS_STANDIN_QT_H
#define HAROS_STANDIN_QT_H
#include <string>
#include <vector>
#define Q_OBJECT
#define Q_GADGET
#define Q_SIGNALS public
#define Q_SLOTS
#define signals public
#define slots
#define emit
#define Q_EMIT
#define Q_DECL_OVERRIDE override
#define Q_UNUSED(x) (void)(x)
#define Q_PROPERTY(x)
#define Q_INVOKABLE
#define Q_DECLARE_METATYPE(x)
#define SIGNAL(x) "2" #x
#define SLOT(x) "1" #x
typedef double qreal;
typedef unsigned int QRgb;
inline QRgb qRgb(int r, int g, int b) { return 0xff000000u | (r << 16) | (g << 8) | b; }
inline int qRed(QRgb rgb) { return (rgb >> 16) & 0xff; }
inline int qGreen(QRgb rgb) { return (rgb >> 8) & 0xff; }
inline int qBlue(QRgb rgb) { return rgb & 0xff; }
namespace Qt {
enum WindowType { Widget = 0, Window = 1, Dialog = 3, Tool = 11, FramelessWindowHint = 0x800 };
typedef int WindowFlags;
enum GlobalColor { color0, color1, black, white, darkGray, gray, lightGray, red, green, blue,
                   cyan, magenta, yellow, darkRed, darkGreen, darkBlue, darkCyan, darkMagenta,
                   darkYellow, transparent };
enum Key { Key_Escape = 0x01000000, Key_Left = 0x01000012, Key_Up, Key_Right, Key_Down,
           Key_Space = 0x20 };
enum FocusPolicy { NoFocus = 0, TabFocus = 1, ClickFocus = 2, StrongFocus = 11 };
enum AlignmentFlag { AlignLeft = 1, AlignRight = 2, AlignHCenter = 4, AlignCenter = 0x84 };
}
// the members a unit uses that this file does not declare (``QWidget::setMaximumSize``):
// the synthesised names' header (read first) defines this class with each of them as a
// static member of its permissive class (``synthesis.QT_MORE``); each class here finds
// it through one base (QWidget through QObject), so a member of a class here hides it
#ifndef HAROS_QT_MORE_DEFINED
struct haros_qt_more {};
#endif
class QStringList;
class QString : public haros_qt_more {
public:
  QString();
  QString(const char* text);
  QString(const QString& other);
  static QString fromStdString(const std::string& text);
  static QString number(double value, char format = 'g', int precision = 6);
  std::string toStdString() const;
  QString arg(const QString& a) const;
  QString arg(double a) const;
  bool isEmpty() const;
  int size() const;
  int toInt(bool* ok = nullptr) const;
  double toDouble(bool* ok = nullptr) const;
  QString& operator=(const QString& other);
  QString operator+(const QString& other) const;
  bool operator==(const QString& other) const;
  QStringList split(const QString& separator) const;
  QString& replace(const QString& before, const QString& after);
  bool startsWith(const QString& text) const;
  bool endsWith(const QString& text) const;
  bool contains(const QString& text) const;
};
template<class T> class QList : public haros_qt_more {
public:
  QList();
  void append(const T& value);
  int size() const;
  T& operator[](int i);
  const T& at(int i) const;
  bool isEmpty() const;
  void clear();
  T& first();
  T& last();
  void push_back(const T& value);
  void resize(int size);
  QList<T>& operator<<(const T& value);
  QList<T>& operator<<(const QList<T>& other);
};
template<class T> class QVector : public QList<T> {};
class QStringList : public QList<QString> {};
class QVariant : public haros_qt_more {
public:
  QVariant();
  template<class T> QVariant(const T& value);
  QString toString() const;
  int toInt(bool* ok = nullptr) const;
  double toDouble(bool* ok = nullptr) const;
  bool toBool() const;
};
class QObject : public haros_qt_more {
public:
  explicit QObject(QObject* parent = nullptr);
  virtual ~QObject();
  static bool connect(const QObject* sender, const char* signal, const QObject* receiver,
                      const char* method);
  template<class A, class B, class C, class D>
  static bool connect(A sender, B signal, C receiver, D method);
  template<class A, class B, class C>
  static bool connect(A sender, B signal, C functor);
  static bool disconnect(const QObject* sender, const char* signal, const QObject* receiver,
                         const char* method);
  void setObjectName(const QString& name);
  QString objectName() const;
  static QString tr(const char* text, const char* disambiguation = nullptr, int n = -1);
  QObject* parent() const;
  void deleteLater();
  bool blockSignals(bool block);
  void installEventFilter(QObject* filter);
};
class QEvent : public haros_qt_more { public: virtual ~QEvent(); int type() const; void accept(); void ignore(); };
class QTimerEvent : public QEvent {};
class QCloseEvent : public QEvent {};
class QShowEvent : public QEvent {};
class QResizeEvent : public QEvent {};
class QPaintEvent : public QEvent {};
class QKeyEvent : public QEvent { public: int key() const; QString text() const; };
class QMouseEvent : public QEvent { public: int x() const; int y() const; int button() const; };
class QWheelEvent : public QEvent {};
class QTimer : public QObject {
public:
  explicit QTimer(QObject* parent = nullptr);
  void start();
  void start(int msec);
  void stop();
  void setInterval(int msec);
  int interval() const;
  void setSingleShot(bool single);
  bool isActive() const;
  template<class F> static void singleShot(int msec, F functor);
  static void singleShot(int msec, const QObject* receiver, const char* member);
  void timeout();
};
class QThread : public QObject {
public:
  explicit QThread(QObject* parent = nullptr);
  void start();
  void quit();
  bool wait(unsigned long msec = 0xffffffff);
  bool isRunning() const;
  static void msleep(unsigned long msec);
  static void sleep(unsigned long secs);
protected:
  virtual void run();
};
class QMutex : public haros_qt_more { public: QMutex(); void lock(); void unlock(); bool tryLock(int timeout = 0); };
class QMutexLocker : public haros_qt_more { public: explicit QMutexLocker(QMutex* mutex); ~QMutexLocker(); };
class QPoint : public haros_qt_more { public: QPoint(); QPoint(int x, int y); int x() const; int y() const; };
class QPointF : public haros_qt_more {
public:
  QPointF();
  QPointF(double x, double y);
  QPointF(const QPoint& p);
  double x() const;
  double y() const;
  double& rx();
  double& ry();
  void setX(double x);
  void setY(double y);
  QPoint toPoint() const;
  QPointF& operator+=(const QPointF& p);
  QPointF& operator-=(const QPointF& p);
  QPointF& operator*=(double c);
};
QPointF operator+(const QPointF& a, const QPointF& b);
QPointF operator-(const QPointF& a, const QPointF& b);
QPointF operator*(const QPointF& p, double c);
QPointF operator*(double c, const QPointF& p);
QPointF operator/(const QPointF& p, double c);
class QTransform : public haros_qt_more {
public:
  QTransform();
  QTransform& rotate(double angle);
  QTransform& translate(double dx, double dy);
  QTransform& scale(double sx, double sy);
};
class QSize : public haros_qt_more { public: QSize(); QSize(int w, int h); int width() const; int height() const; };
class QRect : public haros_qt_more { public: QRect(); QRect(int x, int y, int w, int h); int width() const; int height() const; };
class QColor : public haros_qt_more { public: QColor(); QColor(Qt::GlobalColor color); QColor(QRgb rgb); QColor(int r, int g, int b, int a = 255); QColor(const char* name); };
class QPaintDevice { public: virtual ~QPaintDevice(); };  // (QWidget has it through QObject)
class QImage : public QPaintDevice, public haros_qt_more {
public:
  enum Format { Format_RGB888, Format_RGB32, Format_ARGB32, Format_Grayscale8, Format_Indexed8 };
  QImage();
  QImage(int width, int height, Format format);
  QImage(const unsigned char* data, int width, int height, int bytes_per_line, Format format);
  QImage copy() const;
  QImage scaled(int w, int h) const;
  QImage rgbSwapped() const;
  bool isNull() const;
  int width() const;
  int height() const;
  unsigned char* bits();
  bool load(const QString& file, const char* format = nullptr);
  void fill(unsigned int pixel);
  void fill(const QColor& color);
  QRgb pixel(const QPoint& position) const;
  QRgb pixel(int x, int y) const;
  QImage transformed(const QTransform& matrix) const;
  QSize size() const;
};
class QPixmap : public haros_qt_more { public: QPixmap(); static QPixmap fromImage(const QImage& image); };
class QPen : public haros_qt_more { public: QPen(); QPen(const QColor& color); void setWidth(int width); };
class QBrush : public haros_qt_more { public: QBrush(); QBrush(const QColor& color); QBrush(Qt::GlobalColor color); };
class QPainter : public haros_qt_more {
public:
  QPainter();
  explicit QPainter(QPaintDevice* device);
  void setPen(const QPen& pen);
  void setBrush(const QBrush& brush);
  void drawLine(const QPointF& a, const QPointF& b);
  void drawLine(int x1, int y1, int x2, int y2);
  void drawImage(const QRect& target, const QImage& image);
  void drawImage(int x, int y, const QImage& image);
  void drawImage(const QPointF& point, const QImage& image);
  void drawLine(const QPoint& a, const QPoint& b);
  void drawText(int x, int y, const QString& text);
  void drawEllipse(const QPointF& center, double rx, double ry);
  void fillRect(const QRect& rect, const QColor& color);
  void fillRect(int x, int y, int width, int height, const QColor& color);
  void translate(double dx, double dy);
  void rotate(double angle);
  void scale(double sx, double sy);
};
class QLayout : public QObject { public: void addWidget(class QWidget* widget); };
class QWidget : public QObject, public QPaintDevice {
public:
  explicit QWidget(QWidget* parent = nullptr, Qt::WindowFlags f = Qt::Widget);
  void show();
  void hide();
  void close();
  void update();
  void repaint();
  void resize(int w, int h);
  void setFixedSize(int w, int h);
  void setMinimumSize(int w, int h);
  void setWindowTitle(const QString& title);
  void setLayout(QLayout* layout);
  void setEnabled(bool enabled);
  void setVisible(bool visible);
  void setFocusPolicy(int policy);
  void setFocus();
  int width() const;
  int height() const;
  QRect rect() const;
protected:
  virtual void paintEvent(QPaintEvent* event);
  virtual void keyPressEvent(QKeyEvent* event);
  virtual void keyReleaseEvent(QKeyEvent* event);
  virtual void mousePressEvent(QMouseEvent* event);
  virtual void mouseReleaseEvent(QMouseEvent* event);
  virtual void mouseMoveEvent(QMouseEvent* event);
  virtual void resizeEvent(QResizeEvent* event);
  virtual void closeEvent(QCloseEvent* event);
  virtual void timerEvent(QTimerEvent* event);
};
class QFrame : public QWidget {
public:
  explicit QFrame(QWidget* parent = nullptr, Qt::WindowFlags f = Qt::Widget);
};
class QMainWindow : public QWidget {
public:
  explicit QMainWindow(QWidget* parent = nullptr, Qt::WindowFlags flags = Qt::Widget);
  void setCentralWidget(QWidget* widget);
};
class QDialog : public QWidget { public: explicit QDialog(QWidget* parent = nullptr); int exec(); };
class QLabel : public QFrame {
public:
  explicit QLabel(QWidget* parent = nullptr);
  QLabel(const QString& text, QWidget* parent = nullptr);
  void setText(const QString& text);
  void setPixmap(const QPixmap& pixmap);
};
class QAbstractButton : public QWidget {
public:
  void setText(const QString& text);
  bool isChecked() const;
  void setChecked(bool checked);
  void clicked(bool checked = false);
  void toggled(bool checked);
};
class QPushButton : public QAbstractButton {
public:
  explicit QPushButton(QWidget* parent = nullptr);
  QPushButton(const QString& text, QWidget* parent = nullptr);
};
class QCheckBox : public QAbstractButton { public: explicit QCheckBox(QWidget* parent = nullptr); };
class QLineEdit : public QWidget {
public:
  explicit QLineEdit(QWidget* parent = nullptr);
  QString text() const;
  void setText(const QString& text);
};
class QSlider : public QWidget { public: explicit QSlider(QWidget* parent = nullptr); int value() const; void setValue(int v); void setRange(int a, int b); };
class QSpinBox : public QWidget { public: explicit QSpinBox(QWidget* parent = nullptr); int value() const; void setValue(int v); };
class QComboBox : public QWidget { public: explicit QComboBox(QWidget* parent = nullptr); void addItem(const QString& text); QString currentText() const; int currentIndex() const; };
class QBoxLayout : public QLayout { public: void addLayout(QLayout* layout); void addStretch(int stretch = 0); };
class QVBoxLayout : public QBoxLayout { public: QVBoxLayout(); explicit QVBoxLayout(QWidget* parent); };
class QHBoxLayout : public QBoxLayout { public: QHBoxLayout(); explicit QHBoxLayout(QWidget* parent); };
class QGridLayout : public QLayout { public: QGridLayout(); explicit QGridLayout(QWidget* parent); void addWidget(QWidget* w, int row, int col); };
class QCoreApplication : public QObject {
public:
  QCoreApplication(int& argc, char** argv);
  static int exec();
  static void quit();
  static void processEvents();
  static QCoreApplication* instance();
};
class QApplication : public QCoreApplication { public: QApplication(int& argc, char** argv); };
// the application object, as qapplication.h defines it (connect(..., qApp, SLOT(aboutQt())))
#define qApp (static_cast<QApplication*>(QCoreApplication::instance()))
#endif
