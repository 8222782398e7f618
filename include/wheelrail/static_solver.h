/**
 * @file static_solver.h
 * Moved to <wheelrail/solver/static_solver.h>; this forwarding header keeps the old
 * include line working until every includer names the new path.
 */
#include <wheelrail/solver/static_solver.h>
