#include <tf/haros_tf.h>
