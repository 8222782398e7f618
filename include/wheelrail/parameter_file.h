// Forwarding header until the includes name <wheelrail/parameters/parameter_file.h>.
#include <wheelrail/parameters/parameter_file.h>
