/**
 * @file explicit_solver.h
 * Moved to <wheelrail/solver/explicit_solver.h>; this forwarding header keeps the old
 * include line working until every includer names the new path.
 */
#include <wheelrail/solver/explicit_solver.h>
