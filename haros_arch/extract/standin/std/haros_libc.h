// haros_arch stand-in: the C library parts node code uses (declarations only)
#ifndef HAROS_STANDIN_LIBC_H
#define HAROS_STANDIN_LIBC_H
typedef __SIZE_TYPE__ size_t;
typedef __PTRDIFF_TYPE__ ptrdiff_t;
typedef __INT8_TYPE__ int8_t;
typedef __INT16_TYPE__ int16_t;
typedef __INT32_TYPE__ int32_t;
typedef __INT64_TYPE__ int64_t;
typedef __UINT8_TYPE__ uint8_t;
typedef __UINT16_TYPE__ uint16_t;
typedef __UINT32_TYPE__ uint32_t;
typedef __UINT64_TYPE__ uint64_t;
typedef __INTPTR_TYPE__ intptr_t;
typedef __UINTPTR_TYPE__ uintptr_t;
typedef __INTMAX_TYPE__ intmax_t;
typedef __UINTMAX_TYPE__ uintmax_t;
typedef long ssize_t;
typedef long time_t;
typedef int pid_t;
typedef unsigned int uid_t;
// glibc's <sys/types.h> short names (g++ defines _GNU_SOURCE, and the C++ headers bring
// them in: ros2_control_demos' hardware counts with ``uint``)
typedef unsigned long int ulong;
typedef unsigned short int ushort;
typedef unsigned int uint;
// and its BSD ones (ublox_dgnss' USB connection writes ``u_char *`` buffers)
typedef unsigned char u_char;
typedef unsigned short int u_short;
typedef unsigned int u_int;
typedef unsigned long int u_long;
// glibc's <bits/floatn.h> names the TS 18661-3 types as typedefs for a C++ compiler
// that has none of its own (clang, g++ before 13): consai_ros2's controller takes its
// gains as ``_Float64``
typedef float _Float32;
typedef double _Float64;
typedef double _Float32x;
typedef long double _Float64x;
#define PRId8 "d"
#define PRId16 "d"
#define PRId32 "d"
#define PRId64 "ld"
#define PRIu8 "u"
#define PRIu16 "u"
#define PRIu32 "u"
#define PRIu64 "lu"
#define PRIi32 "i"
#define PRIi64 "li"
#define PRIx32 "x"
#define PRIx64 "lx"
#define PRIuPTR "lu"
#define PRIxPTR "lx"
#define PRIXPTR "lX"
#define PRIX32 "X"
#define PRIX64 "lX"
#define PRIdPTR "ld"
typedef unsigned int useconds_t;
typedef __builtin_va_list va_list;
#define va_start(ap, param) __builtin_va_start(ap, param)
#define va_end(ap) __builtin_va_end(ap)
#define va_arg(ap, type) __builtin_va_arg(ap, type)
#ifndef NULL
#define NULL __null
#endif
#define offsetof(t, d) __builtin_offsetof(t, d)
#define INT8_MAX 127
#define INT16_MAX 32767
#define INT32_MAX 2147483647
#define INT64_MAX 9223372036854775807L
#define INT32_MIN (-INT32_MAX - 1)
#define INT64_MIN (-INT64_MAX - 1)
#define UINT8_MAX 255
#define UINT16_MAX 65535
#define UINT32_MAX 4294967295U
#define UINT64_MAX 18446744073709551615UL
#define INT8_MIN (-128)
#define INT16_MIN (-32767 - 1)
#define SIZE_MAX UINT64_MAX
#define INTPTR_MAX INT64_MAX
#define UINTPTR_MAX UINT64_MAX
#define PTRDIFF_MAX INT64_MAX
#define INTMAX_MAX INT64_MAX
#define UINTMAX_MAX UINT64_MAX
#define INT8_C(c) c
#define INT16_C(c) c
#define INT32_C(c) c
#define INT64_C(c) c##L
#define UINT8_C(c) c
#define UINT16_C(c) c
#define UINT32_C(c) c##U
#define UINT64_C(c) c##UL
#define INTMAX_C(c) c##L
#define UINTMAX_C(c) c##UL
#define INT_MAX 2147483647
#define PATH_MAX 4096
#define NAME_MAX 255
#define HOST_NAME_MAX 64
#define INT_MIN (-INT_MAX - 1)
#define UINT_MAX 4294967295U
#define LONG_MAX 9223372036854775807L
#define LONG_MIN (-LONG_MAX - 1L)
#define ULONG_MAX 18446744073709551615UL
#define LLONG_MAX 9223372036854775807LL
#define LLONG_MIN (-LLONG_MAX - 1LL)
#define ULLONG_MAX 18446744073709551615ULL
#define SHRT_MAX 32767
#define SHRT_MIN (-32768)
#define USHRT_MAX 65535
#define SCHAR_MAX 127
#define SCHAR_MIN (-128)
#define UCHAR_MAX 255
#define CHAR_MAX 127
#define CHAR_MIN (-128)
#define CHAR_BIT 8
#define FLT_MAX 3.40282347e+38F
#define FLT_EPSILON 1.19209290e-7F
#define DBL_MAX 1.7976931348623157e+308
#define DBL_MIN 2.2250738585072014e-308
#define DBL_EPSILON 2.2204460492503131e-16
#define M_PI 3.14159265358979323846
#define M_PI_2 1.57079632679489661923
#define M_PI_4 0.78539816339744830962
#define M_E 2.7182818284590452354
#define HUGE_VAL (__builtin_huge_val())
// <math.h>'s evaluation types (FLT_EVAL_METHOD 0: each its own type), std:: in <cmath>
// (smarc2's declare_parameters<std::double_t>)
typedef float float_t;
typedef double double_t;
#define INFINITY (__builtin_inff())
#define NAN (__builtin_nanf(""))
#define EXIT_SUCCESS 0
#define EXIT_FAILURE 1
#define RAND_MAX 2147483647
#define EOF (-1)
#define BUFSIZ 8192
#define _IONBF 2
#define _IOLBF 1
#define _IOFBF 0
#define SCHED_FIFO 1
#define SCHED_RR 2
#define SIGHUP 1
#define SIGINT 2
#define SIGQUIT 3
#define SIGILL 4
#define SIGABRT 6
#define SIGFPE 8
#define SIGKILL 9
#define SIGUSR1 10
#define SIGSEGV 11
#define SIGUSR2 12
#define SIGPIPE 13
#define SIGALRM 14
#define SIGTERM 15
#define SIGCHLD 17
#define SIG_DFL ((void (*)(int))0)
#define SIG_IGN ((void (*)(int))1)
#define errno (*__errno_location())
// <errno.h>: the error numbers (Linux's values)
#define EPERM 1
#define ENOENT 2
#define EINTR 4
#define EIO 5
#define ENXIO 6
#define EBADF 9
#define EAGAIN 11
#define EWOULDBLOCK EAGAIN
#define ENOMEM 12
#define EACCES 13
#define EBUSY 16
#define EEXIST 17
#define ENODEV 19
#define EINVAL 22
#define ENOSPC 28
#define EPIPE 32
#define ERANGE 34
#define EADDRINUSE 98
#define ECONNRESET 104
#define ETIMEDOUT 110
#define ECONNREFUSED 111
#define EINPROGRESS 115
#define assert(expr) ((void)(expr))
#define CLOCK_MONOTONIC 1
#define ICANON 2
#define ECHO 8
#define TCSANOW 0
#define VMIN 6
#define VTIME 5
#define VEOL 11
#define VEOF 4
#define POLLIN 1
#define POLLPRI 2
#define POLLOUT 4
#define POLLERR 8
#define POLLHUP 16
#define POLLNVAL 32
#define O_RDWR 2
#define O_RDONLY 0
#define O_WRONLY 1
#define O_CREAT 64
#define O_EXCL 128
#define O_TRUNC 512
#define CLOCK_REALTIME 0
extern "C" {
int* __errno_location();
typedef struct haros_FILE FILE;
extern FILE* stdin;
extern FILE* stdout;
extern FILE* stderr;
int printf(const char* format, ...);
int fprintf(FILE* stream, const char* format, ...);
int sprintf(char* str, const char* format, ...);
int snprintf(char* str, size_t size, const char* format, ...);
int vsnprintf(char* str, size_t size, const char* format, va_list ap);
int sscanf(const char* str, const char* format, ...);
int scanf(const char* format, ...);
int puts(const char* s);
int putchar(int c);
int getchar();
FILE* fopen(const char* path, const char* mode);
int fclose(FILE* stream);
size_t fread(void* ptr, size_t size, size_t n, FILE* stream);
size_t fwrite(const void* ptr, size_t size, size_t n, FILE* stream);
char* fgets(char* s, int size, FILE* stream);
int fflush(FILE* stream);
int setvbuf(FILE* stream, char* buf, int mode, size_t size);
void setbuf(FILE* stream, char* buf);
void setlinebuf(FILE* stream);  // glibc's (xarm_ros2's driver: setlinebuf(stdout))
int fgetc(FILE* stream);
int getc(FILE* stream);
int ungetc(int c, FILE* stream);
int fputc(int c, FILE* stream);
int fputs(const char* s, FILE* stream);
int fscanf(FILE* stream, const char* format, ...);
int feof(FILE* stream);
int ferror(FILE* stream);
void clearerr(FILE* stream);
int fseek(FILE* stream, long offset, int whence);
long ftell(FILE* stream);
void rewind(FILE* stream);
int fileno(FILE* stream);
FILE* popen(const char* command, const char* type);
int pclose(FILE* stream);
int remove(const char* path);
int rename(const char* from, const char* to);
struct sched_param { int sched_priority; };
int sched_setscheduler(int pid, int policy, const struct sched_param* param);
int sched_getscheduler(int pid);
int sched_get_priority_max(int policy);
int sched_get_priority_min(int policy);
int sched_yield(void);
void perror(const char* s);
void* malloc(size_t size);
void* calloc(size_t n, size_t size);
void* realloc(void* ptr, size_t size);
void free(void* ptr);
void exit(int status);
void abort();
int atexit(void (*f)());
char* getenv(const char* name);
int setenv(const char* name, const char* value, int overwrite);
int system(const char* command);
int atoi(const char* s);
long atol(const char* s);
double atof(const char* s);
long strtol(const char* s, char** end, int base);
unsigned long strtoul(const char* s, char** end, int base);
double strtod(const char* s, char** end);
long long atoll(const char* s);
long long strtoll(const char* s, char** end, int base);
unsigned long long strtoull(const char* s, char** end, int base);
float strtof(const char* s, char** end);
long double strtold(const char* s, char** end);
long long llabs(long long x);
typedef struct { int quot, rem; } div_t;
typedef struct { long quot, rem; } ldiv_t;
typedef struct { long long quot, rem; } lldiv_t;
div_t div(int x, int y);
ldiv_t ldiv(long x, long y);
lldiv_t lldiv(long long x, long long y);
void qsort(void* base, size_t n, size_t size, int (*compare)(const void*, const void*));
void* bsearch(const void* key, const void* base, size_t n, size_t size,
              int (*compare)(const void*, const void*));
int rand();
void srand(unsigned seed);
double drand48(void);
void srand48(long seed);
long lrand48(void);
int abs(int x);
long labs(long x);
size_t strlen(const char* s);
size_t strnlen(const char* s, size_t n);
int strcmp(const char* a, const char* b);
int strncmp(const char* a, const char* b, size_t n);
// <strings.h>, which glibc's <string.h> includes: unitree_legged_real's ros_udp.cpp
int strcasecmp(const char* a, const char* b);
int strncasecmp(const char* a, const char* b, size_t n);
void bzero(void* s, size_t n);
char* strcpy(char* d, const char* s);
char* strncpy(char* d, const char* s, size_t n);
char* strcat(char* d, const char* s);
char* strncat(char* d, const char* s, size_t n);
char* strchr(const char* s, int c);
char* strrchr(const char* s, int c);
char* strpbrk(const char* s, const char* accept);
size_t strspn(const char* s, const char* accept);
size_t strcspn(const char* s, const char* reject);
void* memchr(const void* s, int c, size_t n);
char* strstr(const char* s, const char* t);
char* strdup(const char* s);
char* strtok(char* s, const char* delim);
char* strtok_r(char* s, const char* delim, char** saveptr);
char* strerror(int errnum);
void* memcpy(void* d, const void* s, size_t n);
void* memmove(void* d, const void* s, size_t n);
void* memset(void* d, int c, size_t n);
int memcmp(const void* a, const void* b, size_t n);
int isalpha(int c);
int isdigit(int c);
int isspace(int c);
int isalnum(int c);
int isupper(int c);
int islower(int c);
int ispunct(int c);
int isxdigit(int c);
int toupper(int c);
int tolower(int c);
double sqrt(double x);
double pow(double x, double y);
double exp(double x);
double log(double x);
double log10(double x);
double sin(double x);
double cos(double x);
double tan(double x);
double asin(double x);
double acos(double x);
double atan(double x);
double atan2(double y, double x);
double sinh(double x);
double cosh(double x);
double tanh(double x);
double fabs(double x);
double floor(double x);
double ceil(double x);
double round(double x);
double trunc(double x);
double fmod(double x, double y);
double hypot(double x, double y);
float hypotf(float x, float y);
// glibc's GNU extension (hector_quadrotor's attitude controller: ``sincos(yaw, &s, &c)``)
void sincos(double x, double* s, double* c);
void sincosf(float x, float* s, float* c);
double nan(const char* tag);
float nanf(const char* tag);
double copysign(double x, double y);
double fmin(double x, double y);
double fmax(double x, double y);
long lround(double x);
float sqrtf(float x);
float fabsf(float x);
float sinf(float x);
float cosf(float x);
float atan2f(float y, float x);
// the rest of <math.h> that node code calls: the float forms, C99's functions
float tanf(float x);
float asinf(float x);
float acosf(float x);
float atanf(float x);
float expf(float x);
float logf(float x);
float log10f(float x);
float powf(float x, float y);
float floorf(float x);
float ceilf(float x);
float roundf(float x);
float truncf(float x);
float fmodf(float x, float y);
float fminf(float x, float y);
float fmaxf(float x, float y);
float copysignf(float x, float y);
long lroundf(float x);
// the long double forms (ros_whill's odometry: ``cosl(pose.theta + ...)``)
long double sqrtl(long double x);
long double fabsl(long double x);
long double sinl(long double x);
long double cosl(long double x);
long double tanl(long double x);
long double asinl(long double x);
long double acosl(long double x);
long double atanl(long double x);
long double atan2l(long double y, long double x);
long double powl(long double x, long double y);
long double expl(long double x);
long double logl(long double x);
long double floorl(long double x);
long double ceill(long double x);
long double roundl(long double x);
long double fmodl(long double x, long double y);
long double hypotl(long double x, long double y);
double asinh(double x);
double acosh(double x);
double atanh(double x);
double log2(double x);
double exp2(double x);
double log1p(double x);
double expm1(double x);
double cbrt(double x);
double remainder(double x, double y);
double rint(double x);
double nearbyint(double x);
long lrint(double x);
long long llround(double x);
long long llrint(double x);
double fdim(double x, double y);
double fma(double x, double y, double z);
double erf(double x);
double erfc(double x);
double tgamma(double x);
double lgamma(double x);
double frexp(double x, int* exponent);
double ldexp(double x, int exponent);
double modf(double x, double* integral);
double scalbn(double x, int n);
int isnan(double x);
int isinf(double x);
int isfinite(double x);
// glibc's BSD forms, which <math.h> declares for g++ (_GNU_SOURCE): a copy of
// gazebo_plugins' diff drive tests ``isnanf(w)``
int isnanf(float x);
int isinff(float x);
int finite(double x);
int finitef(float x);
struct timespec { time_t tv_sec; long tv_nsec; };
struct timeval { time_t tv_sec; long tv_usec; };
time_t time(time_t* t);
typedef long clock_t;
#define CLOCKS_PER_SEC ((clock_t)1000000)
clock_t clock(void);
double difftime(time_t end, time_t begin);
typedef int clockid_t;
int clock_gettime(clockid_t clock, struct timespec* ts);
int gettimeofday(struct timeval* tv, void* tz);
int nanosleep(const struct timespec* req, struct timespec* rem);
#define TIMER_ABSTIME 1
int clock_nanosleep(int clock, int flags, const struct timespec* req, struct timespec* rem);
unsigned int sleep(unsigned int seconds);
int usleep(useconds_t usec);
#define STDIN_FILENO 0
#define STDOUT_FILENO 1
#define STDERR_FILENO 2
int isatty(int fd);
pid_t getpid();
pid_t getppid();
uid_t getuid();
int gethostname(char* name, size_t len);
char* getcwd(char* buf, size_t size);
int access(const char* path, int mode);
int unlink(const char* path);
#define F_OK 0
#define R_OK 4
#define W_OK 2
#define X_OK 1
int close(int fd);
// <unistd.h>'s descriptors and processes (urg_node's getID redirects its output)
int dup(int fd);
int dup2(int fd, int fd2);
int pipe(int fds[2]);
pid_t fork(void);
pid_t setsid(void);
int chdir(const char* path);
int fsync(int fd);
int execv(const char* path, char* const argv[]);
int execvp(const char* file, char* const argv[]);
int execl(const char* path, const char* arg, ...);
int execlp(const char* file, const char* arg, ...);
// <sys/wait.h>
pid_t wait(int* status);
pid_t waitpid(pid_t pid, int* status, int options);
#define WNOHANG 1
#define WEXITSTATUS(status) (((status) & 0xff00) >> 8)
#define WIFEXITED(status) (((status) & 0x7f) == 0)
ssize_t read(int fd, void* buf, size_t count);
ssize_t write(int fd, const void* buf, size_t count);
int open(const char* path, int flags, ...);
struct termios { unsigned c_iflag, c_oflag, c_cflag, c_lflag; unsigned char c_cc[32]; };
int tcgetattr(int fd, struct termios* t);
int tcsetattr(int fd, int when, const struct termios* t);
// <termios.h> and <fcntl.h> of a serial-port driver (Linux's values)
typedef unsigned int speed_t;
typedef unsigned int tcflag_t;
typedef unsigned char cc_t;
int cfmakeraw(struct termios* t);
speed_t cfgetispeed(const struct termios* t);
speed_t cfgetospeed(const struct termios* t);
int cfsetispeed(struct termios* t, speed_t speed);
int cfsetospeed(struct termios* t, speed_t speed);
int cfsetspeed(struct termios* t, speed_t speed);
int tcflush(int fd, int queue);
int tcdrain(int fd);
int tcsendbreak(int fd, int duration);
int tcflow(int fd, int action);
int fcntl(int fd, int cmd, ...);
#define B0 0
#define B300 0000007
#define B600 0000010
#define B1200 0000011
#define B1800 0000012
#define B2400 0000013
#define B4800 0000014
#define B9600 0000015
#define B19200 0000016
#define B38400 0000017
#define B57600 0010001
#define B115200 0010002
#define B230400 0010003
#define B460800 0010004
#define B500000 0010005
#define B576000 0010006
#define B921600 0010007
#define B1000000 0010010
#define B1152000 0010011
#define B1500000 0010012
#define B2000000 0010013
#define B2500000 0010014
#define B3000000 0010015
#define B3500000 0010016
#define B4000000 0010017
#define CBAUD 0010017
#define CSIZE 0000060
#define CS5 0000000
#define CS6 0000020
#define CS7 0000040
#define CS8 0000060
#define CSTOPB 0000100
#define CREAD 0000200
#define PARENB 0000400
#define PARODD 0001000
#define HUPCL 0002000
#define CLOCAL 0004000
#define CRTSCTS 020000000000
#define IGNBRK 0000001
#define BRKINT 0000002
#define IGNPAR 0000004
#define PARMRK 0000010
#define INPCK 0000020
#define ISTRIP 0000040
#define INLCR 0000100
#define IGNCR 0000200
#define ICRNL 0000400
#define IXON 0002000
#define IXANY 0004000
#define IXOFF 0010000
#define OPOST 0000001
#define ONLCR 0000004
#define OCRNL 0000010
#define ISIG 0000001
#define ECHOE 0000020
#define ECHOK 0000040
#define ECHONL 0000100
#define NOFLSH 0000200
#define IEXTEN 0100000
#define TCSADRAIN 1
#define TCSAFLUSH 2
#define TCIFLUSH 0
#define TCOFLUSH 1
#define TCIOFLUSH 2
#define O_NOCTTY 0400
#define O_APPEND 02000
#define O_NONBLOCK 04000
#define O_NDELAY O_NONBLOCK
#define O_SYNC 04010000
#define O_CLOEXEC 02000000
#define F_GETFD 1
#define F_SETFD 2
#define F_GETFL 3
#define F_SETFL 4
#define FD_CLOEXEC 1
#define FIONREAD 0x541B
#define TIOCEXCL 0x540C
#define TIOCMGET 0x5415
#define TIOCMBIS 0x5416
#define TIOCMBIC 0x5417
#define TIOCMSET 0x5418
#define TIOCM_DTR 0x002
#define TIOCM_RTS 0x004
struct pollfd { int fd; short events; short revents; };
int poll(struct pollfd* fds, unsigned long n, int timeout);
int ioctl(int fd, unsigned long request, ...);
typedef void (*sighandler_t)(int);
sighandler_t signal(int signum, sighandler_t handler);
typedef struct { unsigned long haros_bits[16]; } sigset_t;
typedef struct { int si_signo; int si_errno; int si_code; } siginfo_t;
struct sigaction {
  void (*sa_handler)(int);
  void (*sa_sigaction)(int, siginfo_t*, void*);
  sigset_t sa_mask;
  int sa_flags;
  void (*sa_restorer)(void);
};
int sigaction(int signum, const struct sigaction* act, struct sigaction* old);
int sigemptyset(sigset_t* set);
int sigfillset(sigset_t* set);
int sigaddset(sigset_t* set, int signum);
int raise(int sig);
int kill(int pid, int sig);
// <pwd.h>
struct passwd { char* pw_name; char* pw_passwd; uid_t pw_uid; unsigned pw_gid;
                char* pw_gecos; char* pw_dir; char* pw_shell; };
struct passwd* getpwuid(uid_t uid);
struct passwd* getpwnam(const char* name);
// <time.h>: broken-down time
struct tm { int tm_sec, tm_min, tm_hour, tm_mday, tm_mon, tm_year, tm_wday, tm_yday,
  tm_isdst; long tm_gmtoff; const char* tm_zone; };
struct tm* localtime(const time_t* t);
struct tm* gmtime(const time_t* t);
struct tm* localtime_r(const time_t* t, struct tm* result);
struct tm* gmtime_r(const time_t* t, struct tm* result);
time_t mktime(struct tm* tm);
size_t strftime(char* s, size_t max, const char* format, const struct tm* tm);
// <sys/stat.h>
typedef unsigned int mode_t;
struct stat { unsigned long st_dev, st_ino; mode_t st_mode; unsigned long st_nlink;
  uid_t st_uid; unsigned int st_gid; long st_size; time_t st_atime, st_mtime, st_ctime; };
int stat(const char* path, struct stat* buf);
int fstat(int fd, struct stat* buf);
int lstat(const char* path, struct stat* buf);
int mkdir(const char* path, mode_t mode);
#define S_IFMT 0170000
#define S_IFDIR 0040000
#define S_IFREG 0100000
#define S_ISDIR(m) (((m) & S_IFMT) == S_IFDIR)
#define S_ISREG(m) (((m) & S_IFMT) == S_IFREG)
#define S_IFCHR 0020000
#define S_IFBLK 0060000
#define S_IFLNK 0120000
#define S_ISCHR(m) (((m) & S_IFMT) == S_IFCHR)
#define S_ISBLK(m) (((m) & S_IFMT) == S_IFBLK)
#define S_ISLNK(m) (((m) & S_IFMT) == S_IFLNK)
// <dirent.h>
typedef struct haros_DIR DIR;
struct dirent { unsigned long d_ino; long d_off; unsigned short d_reclen; unsigned char d_type;
  char d_name[256]; };
char* realpath(const char* path, char* resolved);
DIR* opendir(const char* name);
struct dirent* readdir(DIR* dir);
int closedir(DIR* dir);
// <sys/select.h>
typedef struct { long fds_bits[16]; } fd_set;
int select(int nfds, fd_set* readfds, fd_set* writefds, fd_set* exceptfds,
           struct timeval* timeout);
void FD_ZERO(fd_set* set);
void FD_SET(int fd, fd_set* set);
void FD_CLR(int fd, fd_set* set);
int FD_ISSET(int fd, const fd_set* set);
}
typedef unsigned long pthread_t;
typedef struct { char haros_opaque[56]; } pthread_attr_t;
typedef struct { char haros_opaque[40]; } pthread_mutex_t;
int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg);
int pthread_join(pthread_t thread, void** result);
int pthread_attr_init(pthread_attr_t* attr);
int pthread_attr_setschedparam(pthread_attr_t* attr, const struct sched_param* param);
int pthread_attr_setschedpolicy(pthread_attr_t* attr, int policy);
int pthread_attr_setinheritsched(pthread_attr_t* attr, int inherit);
int pthread_setschedparam(pthread_t thread, int policy, const struct sched_param* param);
int pthread_getschedparam(pthread_t thread, int* policy, struct sched_param* param);
pthread_t pthread_self(void);
int pthread_getcpuclockid(pthread_t thread, clockid_t* clock);
// <sched.h>'s CPU sets (glibc's macros, as functions) and the affinity calls
typedef struct { unsigned long haros_bits[16]; } cpu_set_t;
void CPU_ZERO(cpu_set_t* set);
void CPU_SET(int cpu, cpu_set_t* set);
void CPU_CLR(int cpu, cpu_set_t* set);
int CPU_ISSET(int cpu, const cpu_set_t* set);
int CPU_COUNT(const cpu_set_t* set);
int sched_setaffinity(int pid, unsigned long size, const cpu_set_t* set);
int sched_getaffinity(int pid, unsigned long size, cpu_set_t* set);
int pthread_setaffinity_np(pthread_t thread, unsigned long size, const cpu_set_t* set);
int pthread_getaffinity_np(pthread_t thread, unsigned long size, cpu_set_t* set);
typedef struct { char haros_opaque[4]; } pthread_mutexattr_t;
#define PTHREAD_PROCESS_PRIVATE 0
#define PTHREAD_PROCESS_SHARED 1
int pthread_mutexattr_init(pthread_mutexattr_t* attr);
int pthread_mutexattr_destroy(pthread_mutexattr_t* attr);
int pthread_mutexattr_setpshared(pthread_mutexattr_t* attr, int shared);
int pthread_mutex_init(pthread_mutex_t* mutex, const pthread_mutexattr_t* attr);
int pthread_mutex_destroy(pthread_mutex_t* mutex);
int pthread_mutex_lock(pthread_mutex_t* mutex);
int pthread_mutex_trylock(pthread_mutex_t* mutex);
int pthread_mutex_unlock(pthread_mutex_t* mutex);
// <sys/mman.h>, <semaphore.h>, <sys/shm.h>, <unistd.h>'s ftruncate, <malloc.h>
#define PROT_NONE 0
#define PROT_READ 1
#define PROT_WRITE 2
#define MAP_SHARED 1
#define MAP_PRIVATE 2
#define MAP_ANONYMOUS 32
#define MAP_FAILED ((void*)-1)
void* mmap(void* addr, unsigned long length, int prot, int flags, int fd, long offset);
int munmap(void* addr, unsigned long length);
#define MCL_CURRENT 1
#define MCL_FUTURE 2
#define MCL_ONFAULT 4
int mlockall(int flags);
int munlockall(void);
int mlock(const void* addr, unsigned long length);
int munlock(const void* addr, unsigned long length);
int shm_open(const char* name, int oflag, unsigned int mode);
int shm_unlink(const char* name);
int ftruncate(int fd, long length);
typedef struct { char haros_opaque[32]; } sem_t;
#define SEM_FAILED ((sem_t*)0)
sem_t* sem_open(const char* name, int oflag, ...);
int sem_close(sem_t* sem);
int sem_unlink(const char* name);
int sem_wait(sem_t* sem);
int sem_trywait(sem_t* sem);
int sem_post(sem_t* sem);
int sem_init(sem_t* sem, int pshared, unsigned int value);
int sem_destroy(sem_t* sem);
#define IPC_CREAT 512
#define IPC_EXCL 1024
#define IPC_RMID 0
int shmget(int key, unsigned long size, int shmflg);
void* shmat(int shmid, const void* shmaddr, int shmflg);
int shmdt(const void* shmaddr);
int malloc_trim(unsigned long pad);
// <sys/resource.h>
typedef unsigned long rlim_t;
struct rlimit { rlim_t rlim_cur; rlim_t rlim_max; };
#define RLIMIT_CPU 0
#define RLIMIT_DATA 2
#define RLIMIT_STACK 3
#define RLIMIT_NOFILE 7
#define RLIM_INFINITY (~0UL)
int getrlimit(int resource, struct rlimit* rlim);
int setrlimit(int resource, const struct rlimit* rlim);
// <sys/socket.h>, <netinet/in.h>, <arpa/inet.h>, <netdb.h>, <ifaddrs.h>
typedef unsigned int socklen_t;
typedef unsigned short sa_family_t;
typedef unsigned short in_port_t;
typedef unsigned int in_addr_t;
struct sockaddr { sa_family_t sa_family; char sa_data[14]; };
struct sockaddr_storage { sa_family_t ss_family; char haros_opaque[126]; };
struct in_addr { in_addr_t s_addr; };
struct in6_addr { unsigned char s6_addr[16]; };
struct sockaddr_in { sa_family_t sin_family; in_port_t sin_port; struct in_addr sin_addr;
                     unsigned char sin_zero[8]; };
struct sockaddr_in6 { sa_family_t sin6_family; in_port_t sin6_port; unsigned sin6_flowinfo;
                      struct in6_addr sin6_addr; unsigned sin6_scope_id; };
struct ip_mreq { struct in_addr imr_multiaddr; struct in_addr imr_interface; };
#define AF_UNSPEC 0
#define AF_UNIX 1
#define AF_INET 2
#define AF_INET6 10
#define AF_PACKET 17
#define PF_INET AF_INET
#define PF_INET6 AF_INET6
#define SOCK_STREAM 1
#define SOCK_DGRAM 2
#define SOCK_RAW 3
#define SOL_SOCKET 1
#define SO_REUSEADDR 2
#define SO_BROADCAST 6
#define SO_RCVBUF 8
#define SO_RCVTIMEO 20
#define SO_SNDTIMEO 21
#define IPPROTO_IP 0
#define IPPROTO_TCP 6
#define IPPROTO_UDP 17
#define IP_ADD_MEMBERSHIP 35
#define INADDR_ANY ((in_addr_t)0x00000000)
#define INADDR_BROADCAST ((in_addr_t)0xffffffff)
#define INADDR_NONE ((in_addr_t)0xffffffff)
#define INET_ADDRSTRLEN 16
#define INET6_ADDRSTRLEN 46
#define MSG_DONTWAIT 0x40
int socket(int domain, int type, int protocol);
int bind(int fd, const struct sockaddr* addr, socklen_t len);
int connect(int fd, const struct sockaddr* addr, socklen_t len);
int listen(int fd, int backlog);
int accept(int fd, struct sockaddr* addr, socklen_t* len);
long send(int fd, const void* buf, unsigned long n, int flags);
long recv(int fd, void* buf, unsigned long n, int flags);
long sendto(int fd, const void* buf, unsigned long n, int flags, const struct sockaddr* to,
            socklen_t len);
long recvfrom(int fd, void* buf, unsigned long n, int flags, struct sockaddr* from,
              socklen_t* len);
int setsockopt(int fd, int level, int name, const void* value, socklen_t len);
int getsockopt(int fd, int level, int name, void* value, socklen_t* len);
int shutdown(int fd, int how);
unsigned short htons(unsigned short v);
unsigned short ntohs(unsigned short v);
unsigned int htonl(unsigned int v);
unsigned int ntohl(unsigned int v);
in_addr_t inet_addr(const char* text);
int inet_aton(const char* text, struct in_addr* out);
char* inet_ntoa(struct in_addr in);
int inet_pton(int family, const char* text, void* out);
const char* inet_ntop(int family, const void* in, char* out, socklen_t size);
struct hostent { char* h_name; char** h_aliases; int h_addrtype; int h_length;
                 char** h_addr_list; };
struct hostent* gethostbyname(const char* name);
struct addrinfo { int ai_flags; int ai_family; int ai_socktype; int ai_protocol;
                  socklen_t ai_addrlen; struct sockaddr* ai_addr; char* ai_canonname;
                  struct addrinfo* ai_next; };
int getaddrinfo(const char* node, const char* service, const struct addrinfo* hints,
                struct addrinfo** res);
void freeaddrinfo(struct addrinfo* res);
const char* gai_strerror(int code);
struct ifaddrs { struct ifaddrs* ifa_next; char* ifa_name; unsigned int ifa_flags;
                 struct sockaddr* ifa_addr; struct sockaddr* ifa_netmask;
                 struct sockaddr* ifa_broadaddr; void* ifa_data; };
int getifaddrs(struct ifaddrs** list);
void freeifaddrs(struct ifaddrs* list);
#endif
