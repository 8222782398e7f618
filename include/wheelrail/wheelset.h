/**
 * @file wheelset.h
 * Moved to <wheelrail/solver/wheelset.h>; this forwarding header keeps the old
 * include line working until every includer names the new path.
 */
#include <wheelrail/solver/wheelset.h>
