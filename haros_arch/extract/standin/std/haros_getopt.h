// haros_arch stand-in: POSIX getopt, which <unistd.h> and <getopt.h> declare (the
// variables ``values.getopt_option`` reads a name from: ``case 'r': name = optarg;``)
#ifndef HAROS_GETOPT_H
#define HAROS_GETOPT_H
extern "C" {
extern char* optarg;
extern int optind;
extern int opterr;
extern int optopt;
int getopt(int argc, char* const argv[], const char* optstring);
}
#endif
