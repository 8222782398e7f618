// Forwarding header until the includes name <wheelrail/mesh/geometry.h>.
#include <wheelrail/mesh/geometry.h>
