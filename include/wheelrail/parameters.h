// Forwarding header until the includes name <wheelrail/parameters/parameters.h>.
#include <wheelrail/parameters/parameters.h>
