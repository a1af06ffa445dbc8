// haros_arch stand-in for <getopt.h>: getopt and GNU getopt_long with its option table
#include "haros_std.h"
#include "haros_getopt.h"
#ifndef HAROS_GETOPT_LONG_H
#define HAROS_GETOPT_LONG_H
extern "C" {
struct option {
  const char* name;
  int has_arg;
  int* flag;
  int val;
};
#define no_argument 0
#define required_argument 1
#define optional_argument 2
int getopt_long(int argc, char* const argv[], const char* optstring,
                const struct option* longopts, int* longindex);
int getopt_long_only(int argc, char* const argv[], const char* optstring,
                     const struct option* longopts, int* longindex);
}
#endif
