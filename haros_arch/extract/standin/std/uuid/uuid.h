// haros_arch stand-in for libuuid's <uuid/uuid.h> (util-linux; declarations only): make,
// parse, print and compare 128-bit UUIDs
#ifndef HAROS_STANDIN_UUID_H
#define HAROS_STANDIN_UUID_H
#include "../haros_std.h"
extern "C" {
typedef unsigned char uuid_t[16];
void uuid_clear(uuid_t uu);
int uuid_compare(const uuid_t uu1, const uuid_t uu2);
void uuid_copy(uuid_t dst, const uuid_t src);
void uuid_generate(uuid_t out);
void uuid_generate_random(uuid_t out);
void uuid_generate_time(uuid_t out);
int uuid_generate_time_safe(uuid_t out);
int uuid_is_null(const uuid_t uu);
int uuid_parse(const char* in, uuid_t uu);
void uuid_unparse(const uuid_t uu, char* out);
void uuid_unparse_lower(const uuid_t uu, char* out);
void uuid_unparse_upper(const uuid_t uu, char* out);
time_t uuid_time(const uuid_t uu, struct timeval* ret_tv);
int uuid_type(const uuid_t uu);
int uuid_variant(const uuid_t uu);
}
#endif
